// The record of the video a whole render wrote into its output folder (DIR/.softbody-video), so that the next
// whole run into that folder removes it with the earlier frames even when it writes no video, or one of another
// name: an interrupted run must not leave an earlier scene's video beside its own frames. Only a video that
// still holds the bytes it was written with (size and checksum) is removed; one outside the folder is the user's.
#pragma once

#include <filesystem>
#include <string>

namespace output {

inline constexpr const char* kVideoRecordName = ".softbody-video";

// Records `video` as the video of the run that wrote `dir` (replacing an earlier record), when it is a regular
// file directly in `dir`; otherwise removes any earlier record. Throws std::runtime_error when it cannot write.
void record_video(const std::filesystem::path& dir, const std::filesystem::path& video);

// Removes the recorded video of `dir`, if it is still the file recorded (same size and checksum), and the
// record. Returns the removed video's path, or "" when none was removed.
std::string remove_recorded_video(const std::filesystem::path& dir);

}  // namespace output
