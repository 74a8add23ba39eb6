// Frame file names from output.pattern ("frame_%04d.png"): the printf pattern ffmpeg's image reader
// takes as well (ffmpeg -framerate 30 -i DIR/frame_%04d.png).
#pragma once

#include <string>

namespace output {

// Throws softbody::InputError naming `scene_file` and output.pattern unless `pattern` holds exactly one
// integer conversion (%d, %4d or %04d), no other '%' than "%%", no '/', and ends in ".png".
void check_frame_pattern(const std::string& pattern, const std::string& scene_file);

// The file name of frame `index` (the pattern must have passed check_frame_pattern).
std::string frame_file_name(const std::string& pattern, int index);

}  // namespace output
