// The simulation CSV: one row per body per frame, written whole when the run ends (also when it
// diverges: the rows of the frames before are kept).
#pragma once

#include <cstdio>
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
  // With a journal (--resume): every frame's rows are also appended to `journal` as they are made, each with
  // its checksum, so that a killed run loses none; `resume_after` >= 0 continues a journal, keeping its rows
  // of frames 0 .. resume_after (complete lines whose checksum holds: a frame's rows are journalled before its
  // state is cached) and dropping the rest. The journal is removed once the CSV is complete.
  CsvSink(std::filesystem::path path, std::filesystem::path journal, int resume_after);
  ~CsvSink() override;
  void on_frame(int index, double time_s, const sim::World& world) override;
  void finish(bool complete) override;
  const std::string& text() const { return text_; }

  // The highest frame whose rows a journal holds for every one of `bodies` bodies, frames 0 .. that one all
  // complete and undamaged (-1: none).
  static int journalled_through(const std::filesystem::path& journal, std::size_t bodies);

 private:
  std::filesystem::path path_;
  std::string text_;
  std::filesystem::path journal_path_;
  std::FILE* journal_ = nullptr;
};

}  // namespace output
