// PC2 and MDD encoders and the exporter that gathers every frame's positions per body.
#include "output/point_cache.hpp"

#include <bit>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "core/profile.hpp"
#include "output/atomic_file.hpp"
#include "output/mesh_exporter.hpp"
#include "output/shown_surface.hpp"

namespace output {
namespace {

// Appends the bytes of a 32-bit value in the given byte order.
template <typename T>
void append_32bit(std::string& out, T value, std::endian order) {
  static_assert(sizeof(T) == 4);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, 4);
  for (int i = 0; i < 4; ++i) {
    const int shift = order == std::endian::little ? 8 * i : 8 * (3 - i);
    out.push_back(static_cast<char>((bits >> shift) & 0xffu));
  }
}

void append_positions(std::string& out, const PointSamples& samples, std::endian order) {
  for (const float coordinate : samples.xyz) append_32bit(out, coordinate, order);
}

}  // namespace

std::string encode_pc2(const PointSamples& samples, float start_frame, float frames_per_sample) {
  std::string bytes("POINTCACHE2", 12);  // the 11 letters and their terminating NUL
  append_32bit(bytes, std::int32_t{1}, std::endian::little);
  append_32bit(bytes, static_cast<std::int32_t>(samples.points), std::endian::little);
  append_32bit(bytes, start_frame, std::endian::little);
  append_32bit(bytes, frames_per_sample, std::endian::little);
  append_32bit(bytes, static_cast<std::int32_t>(samples.samples()), std::endian::little);
  append_positions(bytes, samples, std::endian::little);
  return bytes;
}

std::string encode_mdd(const PointSamples& samples) {
  std::string bytes;
  append_32bit(bytes, static_cast<std::int32_t>(samples.samples()), std::endian::big);
  append_32bit(bytes, static_cast<std::int32_t>(samples.points), std::endian::big);
  for (const float time : samples.times_s) append_32bit(bytes, time, std::endian::big);
  append_positions(bytes, samples, std::endian::big);
  return bytes;
}

std::string body_to_obj(const sim::World& world, int body, double time_s) {
  char line[96];
  std::snprintf(line, sizeof line, "# softbody body %d at t = %.9g s\n", body, time_s);
  std::string text = line;
  append_obj_object(text, world, body, 1);
  return text;
}

PointCacheExporter::PointCacheExporter(std::filesystem::path dir, PointCacheFormat format)
    : dir_(std::move(dir)), format_(format) {
  std::filesystem::create_directories(dir_);
}

std::filesystem::path PointCacheExporter::mesh_path(int body) const {
  return dir_ / ("body" + std::to_string(body) + ".obj");
}

std::filesystem::path PointCacheExporter::cache_path(int body) const {
  return dir_ / ("body" + std::to_string(body) + (format_ == PointCacheFormat::Pc2 ? ".pc2" : ".mdd"));
}

void PointCacheExporter::on_frame(int index, double time_s, const sim::World& world) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::mesh_write);
  if (first_frame_ < 0) {
    first_frame_ = index;
    for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
      meshes_obj_.push_back(body_to_obj(world, static_cast<int>(b), time_s));
      bodies_.push_back({shown_vertex_count(world, static_cast<int>(b)), {}, {}});
    }
  } else if (index != last_frame_ + 1) {
    throw std::logic_error("a point cache needs frames one after another, got " + std::to_string(index) + " after " +
                           std::to_string(last_frame_));
  }
  last_frame_ = index;
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b) {
    PointSamples& samples = bodies_[b];
    for (const softbody::Vec3& p : shown_.of(world, static_cast<int>(b))) {
      for (int axis = 0; axis < 3; ++axis) samples.xyz.push_back(static_cast<float>(p[axis]));
    }
    samples.times_s.push_back(static_cast<float>(time_s));
  }
}

// Also after a stopped run (diverged): the frames before are valid, and the cache says how many it holds.
void PointCacheExporter::finish(bool /*complete*/) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::mesh_write);
  for (int b = 0; b < body_count(); ++b) {
    const PointSamples& samples = bodies_[static_cast<std::size_t>(b)];
    write_file_atomically(mesh_path(b), meshes_obj_[static_cast<std::size_t>(b)]);
    write_file_atomically(cache_path(b), format_ == PointCacheFormat::Pc2
                                             ? encode_pc2(samples, static_cast<float>(first_frame_), 1.0f)
                                             : encode_mdd(samples));
  }
}

}  // namespace output
