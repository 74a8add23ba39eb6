// Frame file names from output.pattern ("frame_%04d.png"): the printf pattern ffmpeg's image reader
// takes as well (ffmpeg -framerate 30 -i DIR/frame_%04d.png).
#pragma once

#include <string>

namespace output {

// The file name of frame `index` (the pattern must have passed scene::check_frame_pattern).
std::string frame_file_name(const std::string& pattern, int index);

}  // namespace output
