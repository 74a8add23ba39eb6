// `softbody export --format pc2 | mdd` end to end, without Blender: every sample of the caches holds the
// same float32 positions as the binary PLY frame of that frame number, the MDD's times are the frames'
// times, and the frame options a cache cannot honour are bad input.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "test_helpers.hpp"

namespace {

using testing_support::CommandResult;
using testing_support::run_shell;

std::string quoted(const std::filesystem::path& path) {
  std::string text = "'";
  text += path.string();
  text += "'";
  return text;
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string export_command(const std::filesystem::path& out, const std::string& format) {
  return quoted(SOFTBODY_EXE) + " export " +
         quoted(std::filesystem::path(SOFTBODY_TEST_SCENES_DIR) / "render_track.json") + " -o " + quoted(out) +
         " --format " + format;
}

std::uint32_t little_endian_at(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value |= std::uint32_t(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return value;
}

std::uint32_t big_endian_at(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

// The vertex floats of a binary little-endian PLY (x y z per vertex right after the header), as bit patterns.
std::string ply_positions(const std::filesystem::path& path, std::size_t vertices) {
  const std::string bytes = file_bytes(path);
  const std::size_t start = bytes.find("end_header\n") + 11;
  return bytes.substr(start, vertices * 12);
}

TEST(PointCacheExport, EverySampleIsThePlyFrame) {
  const std::filesystem::path out = testing_support::scratch_dir("point_cache_export");
  for (const char* format : {"pc2", "mdd"}) {
    const CommandResult result = run_shell(export_command(out / "cache", format));
    ASSERT_EQ(result.exit_status, 0) << result.output;
  }
  const CommandResult ply = run_shell(export_command(out / "ply", "ply"));
  ASSERT_EQ(ply.exit_status, 0) << ply.output;

  const std::string pc2 = file_bytes(out / "cache" / "body0.pc2");
  const std::string mdd = file_bytes(out / "cache" / "body0.mdd");
  ASSERT_GE(pc2.size(), 32u);
  const std::uint32_t points = little_endian_at(pc2, 16), samples = little_endian_at(pc2, 28);
  EXPECT_EQ(points, 162u);  // icosphere:2
  EXPECT_EQ(samples, 11u);  // 1 s at 10 fps, frame 0 included
  EXPECT_EQ(pc2.size(), 32u + samples * points * 12);
  EXPECT_EQ(big_endian_at(mdd, 0), samples);
  EXPECT_EQ(big_endian_at(mdd, 4), points);
  EXPECT_EQ(mdd.size(), 8u + samples * 4 + samples * points * 12);
  for (std::uint32_t k = 0; k < samples; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04u.ply", k);
    const std::string expected = ply_positions(out / "ply" / name, points);
    ASSERT_EQ(expected.size(), points * 12u);
    EXPECT_EQ(pc2.substr(32 + k * points * 12, points * 12), expected) << "PC2 sample " << k;
    const std::size_t mdd_sample = 8 + samples * 4 + k * points * 12;
    bool same = true;
    for (std::size_t i = 0; i < points * 3u && same; ++i) {
      same = big_endian_at(mdd, mdd_sample + 4 * i) == little_endian_at(expected, 4 * i);
    }
    EXPECT_TRUE(same) << "MDD sample " << k;
    float time = 0.0f;
    const std::uint32_t bits = big_endian_at(mdd, 8 + 4 * k);
    std::memcpy(&time, &bits, 4);
    EXPECT_FLOAT_EQ(time, static_cast<float>(k) / 10.0f) << "MDD time of frame " << k;
  }
  // The OBJ is frame 0's mesh: its first vertex is the PC2's first point.
  const std::string obj = file_bytes(out / "cache" / "body0.obj");
  EXPECT_NE(obj.find("o body0\nv "), std::string::npos);
}

TEST(PointCacheExport, GapsInTheFramesAndResumeAreBadInput) {
  const std::filesystem::path out = testing_support::scratch_dir("point_cache_bad") / "never";
  const CommandResult gaps = run_shell(export_command(out, "pc2") + " --frames 0-2,5-6");
  EXPECT_EQ(gaps.exit_status, 2) << gaps.output;
  EXPECT_NE(gaps.output.find("--frames"), std::string::npos) << gaps.output;
  const CommandResult resume = run_shell(export_command(out, "mdd") + " --resume");
  EXPECT_EQ(resume.exit_status, 2) << resume.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
