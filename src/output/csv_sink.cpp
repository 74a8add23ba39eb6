// CSV rows from per-body diagnostics.
#include "output/csv_sink.hpp"

#include <cstdio>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/profile.hpp"
#include "output/atomic_file.hpp"
#include "output/checked_line.hpp"
#include "output/csv_row.hpp"

namespace output {

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The journal lines of `rows` (whole CSV lines, each ending in '\n'): each row with its checksum, so that a
// row damaged on disk (bytes overwritten, a line cut by a kill) is dropped on resume, never copied into the CSV.
std::string journal_lines(std::string_view rows) {
  std::string lines;
  for (std::size_t start = 0; start < rows.size();) {
    const std::size_t end = rows.find('\n', start);
    lines += checked_line(rows.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

// The frame number that starts a row, or -1 for a line that is not a whole row.
int row_frame(std::string_view line) {
  const std::size_t comma = line.find(',');
  if (comma == std::string_view::npos || comma == 0 || comma > 9) return -1;
  int frame = 0;
  for (char c : line.substr(0, comma)) {
    if (c < '0' || c > '9') return -1;
    frame = 10 * frame + (c - '0');
  }
  return frame;
}

}  // namespace

CsvSink::CsvSink(std::filesystem::path path) : path_(std::move(path)) { text_ = std::string(kCsvHeader) + "\n"; }

CsvSink::CsvSink(std::filesystem::path path, std::filesystem::path journal, int resume_after)
    : CsvSink(std::move(path)) {
  journal_path_ = std::move(journal);
  std::filesystem::create_directories(journal_path_.parent_path());
  std::string kept;
  if (resume_after >= 0) {
    const std::string old = read_text(journal_path_);
    for (std::size_t start = 0; start < old.size();) {
      const std::size_t end = old.find('\n', start);
      if (end == std::string::npos) break;  // a line cut by the kill: not a row
      const std::optional<std::string_view> row = checked_text(std::string_view(old).substr(start, end - start));
      const int frame = row ? row_frame(*row) : -1;
      if (frame >= 0 && frame <= resume_after) kept.append(*row).append("\n");
      start = end + 1;
    }
  }
  write_file_atomically(journal_path_, journal_lines(kept));
  text_ += kept;
  journal_ = std::fopen(journal_path_.c_str(), "ab");
  if (!journal_) throw std::runtime_error(journal_path_.string() + ": cannot open the CSV journal for appending");
}

CsvSink::~CsvSink() {
  if (journal_) std::fclose(journal_);
}

int CsvSink::journalled_through(const std::filesystem::path& journal, std::size_t bodies) {
  const std::string text = read_text(journal);
  std::vector<std::size_t> rows;  // per frame
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) break;
    const std::optional<std::string_view> row = checked_text(std::string_view(text).substr(start, end - start));
    const int frame = row ? row_frame(*row) : -1;
    if (frame >= 0) {
      if (rows.size() <= static_cast<std::size_t>(frame)) rows.resize(static_cast<std::size_t>(frame) + 1, 0);
      ++rows[static_cast<std::size_t>(frame)];
    }
    start = end + 1;
  }
  int through = -1;
  while (through + 1 < static_cast<int>(rows.size()) && rows[static_cast<std::size_t>(through + 1)] == bodies)
    ++through;
  return through;
}

void CsvSink::on_frame(int index, double time_s, const sim::World& world) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::csv_write);
  const std::size_t frame_start = text_.size();
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
    const CsvRow r = csv_row(index, time_s, world, b);
    const auto& v = r.values;
    char row[512];
    // %.17g round-trips doubles exactly.
    std::snprintf(row, sizeof row, "%d,%.17g,%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  r.frame, r.time_s, r.body, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9]);
    text_ += row;
  }
  if (journal_) {
    const std::string lines = journal_lines(std::string_view(text_).substr(frame_start));
    if (std::fwrite(lines.data(), 1, lines.size(), journal_) != lines.size() || std::fflush(journal_) != 0) {
      throw std::runtime_error(journal_path_.string() + ": cannot append to the CSV journal");
    }
  }
}

void CsvSink::finish(bool complete) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::csv_write);
  write_file_atomically(path_, text_);
  if (journal_ && complete) {
    std::fclose(journal_);
    journal_ = nullptr;
    std::filesystem::remove(journal_path_);
  }
}

}  // namespace output
