// The PC2 reader: header, sizes and values checked before any position is used.
#include "mesh/pc2_file.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "core/errors.hpp"
#include "core/file_kind.hpp"

namespace mesh {
namespace {

constexpr std::size_t kHeaderBytes = 32;  // magic 12, version, points, start, rate, samples: 4 each
constexpr char kMagic[12] = {'P', 'O', 'I', 'N', 'T', 'C', 'A', 'C', 'H', 'E', '2', '\0'};

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& what) {
  throw softbody::InputError(file.string() + ": point cache (PC2) " + what);
}

// The little-endian 32-bit value at `offset` of `bytes`.
std::uint32_t bits_at(const std::string& bytes, std::size_t offset) {
  std::uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) bits |= std::uint32_t{static_cast<unsigned char>(bytes[offset + i])} << (8 * i);
  return bits;
}
std::int32_t int_at(const std::string& bytes, std::size_t offset) {
  return std::bit_cast<std::int32_t>(bits_at(bytes, offset));
}
float float_at(const std::string& bytes, std::size_t offset) { return std::bit_cast<float>(bits_at(bytes, offset)); }

std::string read_bytes(const std::filesystem::path& file, const MeshLimits& limits) {
  softbody::require_regular_file(file, limits.max_file_bytes, "point cache",
                                 "raise it with the scene key limits.max_file_mb");
  std::ifstream in(file, std::ios::binary);
  if (!in) refuse(file, "cannot be opened");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) refuse(file, "cannot be read");
  return bytes;
}

}  // namespace

Pc2Cache read_pc2_file(const std::filesystem::path& file, const MeshLimits& limits) {
  const std::string bytes = read_bytes(file, limits);
  if (bytes.size() < kHeaderBytes) {
    refuse(file, "has " + std::to_string(bytes.size()) + " bytes, fewer than its 32-byte header (truncated?)");
  }
  if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    refuse(file, "has a bad header: expected it to start with \"POINTCACHE2\" and a zero byte");
  if (const std::int32_t version = int_at(bytes, 12); version != 1)
    refuse(file, "has a bad header: version " + std::to_string(version) + ", expected 1");
  const std::int32_t points = int_at(bytes, 16), samples = int_at(bytes, 28);
  const float start = float_at(bytes, 20), rate = float_at(bytes, 24);
  if (points <= 0 || points > limits.max_vertices) {
    refuse(file, "has a bad header: " + std::to_string(points) + " points per sample, expected 1 to " +
                     std::to_string(limits.max_vertices) + " (raise it with the scene key limits.max_vertices)");
  }
  if (samples <= 0) refuse(file, "has a bad header: " + std::to_string(samples) + " samples, expected at least 1");
  if (!std::isfinite(start)) refuse(file, "has a bad header: its start frame is not a finite number");
  if (!std::isfinite(rate) || rate <= 0.0f)
    refuse(file, "has a bad header: its sample rate (frames between samples) is not a finite number > 0");
  // The data's size in 64 bits: points and samples are each below 2^31, and 12 × their product below 2^67 does
  // not fit, so the product is checked against the file's size first.
  const auto available = static_cast<std::uintmax_t>(bytes.size() - kHeaderBytes);
  const auto per_sample = static_cast<std::uintmax_t>(points) * 12u;
  if (available / per_sample < static_cast<std::uintmax_t>(samples)) {
    refuse(file, "is truncated: its header announces " + std::to_string(samples) + " samples of " +
                     std::to_string(points) + " points, but it holds " + std::to_string(available / per_sample) +
                     (available / per_sample == 1 ? " whole sample (" : " whole samples (") +
                     std::to_string(bytes.size()) + " bytes)");
  }
  const std::uintmax_t expected = kHeaderBytes + per_sample * static_cast<std::uintmax_t>(samples);
  if (bytes.size() != expected) {
    refuse(file, "has " + std::to_string(bytes.size() - expected) + " bytes after its last sample (expected " +
                     std::to_string(expected) + " bytes for the " + std::to_string(samples) + " samples of " +
                     std::to_string(points) + " points its header announces)");
  }
  Pc2Cache cache;
  cache.points = points;
  cache.start_frame = start;
  cache.frames_per_sample = rate;
  cache.samples.resize(static_cast<std::size_t>(samples));
  std::size_t offset = kHeaderBytes;
  for (std::size_t s = 0; s < cache.samples.size(); ++s) {
    cache.samples[s].resize(static_cast<std::size_t>(points));
    for (std::size_t p = 0; p < cache.samples[s].size(); ++p) {
      for (int axis = 0; axis < 3; ++axis, offset += 4) {
        const double value = float_at(bytes, offset);
        if (!std::isfinite(value) || std::abs(value) > kMaxMeshCoordinate) {
          refuse(file, "holds a coordinate that is not finite or beyond 1e12 (sample " + std::to_string(s) +
                           ", point " + std::to_string(p) + ")");
        }
        cache.samples[s][p][axis] = value;
      }
    }
  }
  return cache;
}

}  // namespace mesh
