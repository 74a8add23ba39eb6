// Frame file name patterns from output.pattern ("frame_%04d.png"): the printf pattern ffmpeg's image reader
// takes as well (ffmpeg -framerate 30 -i DIR/frame_%04d.png).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace output {

// The file name of frame `index` (the pattern must have passed scene::check_frame_pattern).
std::string frame_file_name(const std::string& pattern, int index);

// The frame whose file name under `pattern` is `name` ("frame_0012.png": 12), or nothing for another name.
std::optional<int> frame_index_of(const std::string& pattern, const std::string& name);

// Removes every file in `dir` named by `pattern`, whatever its frame number (an earlier run's frames, before a
// new run writes its own: a run that then fails or is interrupted leaves no mix of two runs). Returns how many.
int remove_frame_files(const std::filesystem::path& dir, const std::string& pattern);

}  // namespace output
