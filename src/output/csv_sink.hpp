// The simulation CSV: one row per body per frame, written whole when the run ends (also when it
// diverges: the rows of the frames before are kept).
#pragma once

#include <filesystem>
#include <string>

#include "frames/frame_sink.hpp"

namespace output {

// The contract's columns, in order (users' scripts read them by name).
inline constexpr const char* kCsvHeader =
    "frame,time,body,com_x,com_y,com_z,vel_x,vel_y,vel_z,volume,kinetic_energy,total_energy,min_y";

class CsvSink final : public frames::FrameSink {
 public:
  explicit CsvSink(std::filesystem::path path);
  void on_frame(int index, double time_s, const sim::World& world) override;
  void finish(bool complete) override;
  const std::string& text() const { return text_; }

 private:
  std::filesystem::path path_;
  std::string text_;
};

}  // namespace output
