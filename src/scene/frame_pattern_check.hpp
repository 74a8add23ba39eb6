// What a frame file name pattern in output.pattern may be ("frame_%04d.png"): the printf pattern ffmpeg's image
// reader takes as well (ffmpeg -framerate 30 -i DIR/frame_%04d.png). Expanding one is output/frame_pattern.hpp.
#pragma once

#include <string>

namespace scene {

// True when `pattern` holds exactly one integer conversion (%d, %4d or %04d), no other '%' than "%%", no '/', and
// ends in `extension` (".png", ".obj").
bool is_frame_pattern(const std::string& pattern, const std::string& extension);

// Throws softbody::InputError naming `scene_file` and output.pattern unless `pattern` holds exactly one
// integer conversion (%d, %4d or %04d), no other '%' than "%%", no '/', and ends in ".png".
void check_frame_pattern(const std::string& pattern, const std::string& scene_file);

}  // namespace scene
