// The PC2 and MDD encoders against the formats' byte layouts, written out by hand here.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "output/point_cache.hpp"

namespace {

// Two samples of two points: (1, 2, 3), (-0.5, 0, 4) at t = 0, then moved by +1 in y at t = 1/30 s.
output::PointSamples two_samples() {
  output::PointSamples samples;
  samples.points = 2;
  samples.xyz = {1.0f, 2.0f, 3.0f, -0.5f, 0.0f, 4.0f, 1.0f, 3.0f, 3.0f, -0.5f, 1.0f, 4.0f};
  samples.times_s = {0.0f, 1.0f / 30.0f};
  return samples;
}

std::uint32_t bits_of(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, 4);
  return bits;
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

TEST(PointCache, Pc2HeaderAndLittleEndianPositions) {
  const std::string bytes = output::encode_pc2(two_samples(), 5.0f, 1.0f);
  ASSERT_EQ(bytes.size(), 32u + 2 * 2 * 12);  // 32-byte header, then 12 bytes per point per sample
  EXPECT_EQ(bytes.substr(0, 12), std::string("POINTCACHE2\0", 12));
  EXPECT_EQ(little_endian_at(bytes, 12), 1u);                        // version
  EXPECT_EQ(little_endian_at(bytes, 16), 2u);                        // points
  EXPECT_EQ(little_endian_at(bytes, 20), bits_of(5.0f));             // start frame
  EXPECT_EQ(little_endian_at(bytes, 24), bits_of(1.0f));             // sample rate
  EXPECT_EQ(little_endian_at(bytes, 28), 2u);                        // samples
  EXPECT_EQ(little_endian_at(bytes, 32), bits_of(1.0f));             // sample 0, point 0, x
  EXPECT_EQ(little_endian_at(bytes, 32 + 4 * 4), bits_of(0.0f));     // sample 0, point 1, y
  EXPECT_EQ(little_endian_at(bytes, 32 + 24 + 4), bits_of(3.0f));    // sample 1, point 0, y
  EXPECT_EQ(little_endian_at(bytes, 32 + 24 + 12), bits_of(-0.5f));  // sample 1, point 1, x
}

TEST(PointCache, MddBigEndianCountsTimesAndPositions) {
  const std::string bytes = output::encode_mdd(two_samples());
  ASSERT_EQ(bytes.size(), 8u + 2 * 4 + 2 * 2 * 12);            // counts, a time per frame, 12 bytes per point per frame
  EXPECT_EQ(big_endian_at(bytes, 0), 2u);                      // frames
  EXPECT_EQ(big_endian_at(bytes, 4), 2u);                      // points
  EXPECT_EQ(big_endian_at(bytes, 8), bits_of(0.0f));           // time of frame 0
  EXPECT_EQ(big_endian_at(bytes, 12), bits_of(1.0f / 30.0f));  // time of frame 1
  EXPECT_EQ(big_endian_at(bytes, 16), bits_of(1.0f));          // frame 0, point 0, x
  EXPECT_EQ(big_endian_at(bytes, 16 + 12 + 8), bits_of(4.0f));   // frame 0, point 1, z
  EXPECT_EQ(big_endian_at(bytes, 16 + 24 + 16), bits_of(1.0f));  // frame 1, point 1, y
}

}  // namespace
