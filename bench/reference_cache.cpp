// Raw binary storage of a BounceRecord: a tag, the sample and vertex counts, then the doubles as they are.
#include "reference_cache.hpp"

#include <cstdint>
#include <fstream>

namespace bench {
namespace {

constexpr std::uint64_t kTag = 0x31656365'72756f62ULL;  // "bounce1e" as bytes: guards against other files

template <class T>
void write(std::ofstream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
bool read(std::ifstream& in, T& value) {
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof value));
}

}  // namespace

std::optional<BounceRecord> load_record(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t tag = 0, samples = 0, vertices = 0;
  if (!in || !read(in, tag) || tag != kTag || !read(in, samples) || !read(in, vertices)) return std::nullopt;
  BounceRecord r;
  if (!read(in, r.dt_s) || !read(in, r.steps) || !read(in, r.wall_s) || !read(in, r.cpu_s)) return std::nullopt;
  r.volume_m3.resize(samples);
  r.com_m.resize(samples);
  r.x_m.assign(samples, std::vector<softbody::Vec3>(vertices));
  for (std::uint64_t s = 0; s < samples; ++s) {
    if (!read(in, r.volume_m3[s]) || !read(in, r.com_m[s])) return std::nullopt;
    for (softbody::Vec3& x : r.x_m[s]) {
      if (!read(in, x)) return std::nullopt;
    }
  }
  return r;
}

void save_record(const BounceRecord& record, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  const std::uint64_t samples = record.volume_m3.size(), vertices = record.x_m.empty() ? 0 : record.x_m[0].size();
  write(out, kTag);
  write(out, samples);
  write(out, vertices);
  write(out, record.dt_s);
  write(out, record.steps);
  write(out, record.wall_s);
  write(out, record.cpu_s);
  for (std::uint64_t s = 0; s < samples; ++s) {
    write(out, record.volume_m3[s]);
    write(out, record.com_m[s]);
    for (const softbody::Vec3& x : record.x_m[s]) write(out, x);
  }
}

BounceRecord load_or_record(const BounceSetup& setup, double duration_s, const std::string& path) {
  if (!path.empty()) {
    if (std::optional<BounceRecord> cached = load_record(path)) return *cached;
  }
  BounceRecord record = record_bounce(setup, duration_s);
  if (!path.empty()) save_record(record, path);
  return record;
}

}  // namespace bench
