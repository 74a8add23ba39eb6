// Writing and reading cached states and the cache's manifest.
#include "output/state_cache.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <xxhash.h>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "sim/model/state_codec.hpp"

namespace output {
namespace {

constexpr char kMagic[16] = {'S', 'O', 'F', 'T', 'B', 'O', 'D', 'Y', ' ', 'S', 'T', 'A', 'T', 'E', '\n', '\0'};
constexpr std::size_t kHeaderBytes = 96;
constexpr std::size_t kCheckedHeaderBytes = 88;  // the header checksum covers the bytes before it

template <class T>
void put(std::string& bytes, T value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
T get(const std::string& bytes, std::size_t& offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  offset += sizeof value;
  return value;
}

std::string read_whole_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) return {};
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace

std::filesystem::path cached_state_path(const std::filesystem::path& dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "state_%06d.bin", frame);
  return dir / name;
}

bool has_cached_state(const std::filesystem::path& dir, int frame) {
  std::error_code ec;
  return std::filesystem::is_regular_file(cached_state_path(dir, frame), ec);
}

std::string cached_state_file(int frame, std::uint64_t scene_hash, const sim::Model& model, const sim::State& state) {
  const std::string payload = sim::encode_state(state);
  std::string bytes;
  bytes.reserve(kHeaderBytes + payload.size());
  bytes.append(kMagic, sizeof kMagic);
  put<std::uint32_t>(bytes, kStateCacheFormat);
  put<std::uint32_t>(bytes, sim::kStateCodecVersion);
  put<std::uint64_t>(bytes, scene_hash);
  put<std::int32_t>(bytes, frame);
  put<std::uint32_t>(bytes, static_cast<std::uint32_t>(model.bodies.size()));
  put<double>(bytes, state.time_s);
  char integrator[16] = {};
  const std::string name = sim::to_string(model.solver.integrator);
  std::memcpy(integrator, name.data(), std::min(name.size(), sizeof integrator - 1));
  bytes.append(integrator, sizeof integrator);
  put<std::uint64_t>(bytes, model.vertex_count());
  put<std::uint64_t>(bytes, payload.size());
  put<std::uint64_t>(bytes, XXH3_64bits(payload.data(), payload.size()));
  put<std::uint64_t>(bytes, XXH3_64bits(bytes.data(), kCheckedHeaderBytes));
  bytes += payload;
  return bytes;
}

void write_cached_state(const std::filesystem::path& dir, int frame, std::uint64_t scene_hash, const sim::Model& model,
                        const sim::State& state) {
  write_file_atomically(cached_state_path(dir, frame), cached_state_file(frame, scene_hash, model, state));
}

sim::State read_cached_state(const std::filesystem::path& dir, int frame, std::uint64_t scene_hash,
                             const sim::Model& model) {
  const std::filesystem::path path = cached_state_path(dir, frame);
  auto refuse = [&](const std::string& why) -> softbody::InputError {
    return softbody::InputError(path.string() + ": " + why);
  };
  if (!has_cached_state(dir, frame)) throw refuse("missing: the cache has no state of frame " + std::to_string(frame));
  const std::string bytes = read_whole_file(path);
  if (bytes.size() < kHeaderBytes) {
    throw refuse("truncated: " + std::to_string(bytes.size()) + " bytes, shorter than the " +
                 std::to_string(kHeaderBytes) + "-byte header");
  }
  if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) throw refuse("not a softbody state file");
  std::size_t offset = sizeof kMagic;
  const auto format = get<std::uint32_t>(bytes, offset);
  const auto codec = get<std::uint32_t>(bytes, offset);
  if (format != kStateCacheFormat || codec != sim::kStateCodecVersion) {
    throw refuse("format " + std::to_string(format) + "." + std::to_string(codec) + ", this program reads " +
                 std::to_string(kStateCacheFormat) + "." + std::to_string(sim::kStateCodecVersion) +
                 " (simulate the scene again with --cache)");
  }
  const auto hash = get<std::uint64_t>(bytes, offset);
  const auto file_frame = get<std::int32_t>(bytes, offset);
  const auto bodies = get<std::uint32_t>(bytes, offset);
  offset += sizeof(double) + 16;  // time and integrator: informative, the payload holds the state
  const auto vertices = get<std::uint64_t>(bytes, offset);
  const auto payload_size = get<std::uint64_t>(bytes, offset);
  const auto payload_checksum = get<std::uint64_t>(bytes, offset);
  const auto header_checksum = get<std::uint64_t>(bytes, offset);
  if (header_checksum != XXH3_64bits(bytes.data(), kCheckedHeaderBytes)) throw refuse("corrupt header (checksum)");
  if (hash != scene_hash) {
    throw refuse("made from another scene or by another build of softbody (scene hash " + hex(hash) +
                 ", this scene's " + hex(scene_hash) + "): simulate this scene with --cache");
  }
  if (file_frame != frame)
    throw refuse("holds frame " + std::to_string(file_frame) + ", expected " + std::to_string(frame));
  if (bodies != model.bodies.size() || vertices != model.vertex_count()) {
    throw refuse("holds " + std::to_string(bodies) + " bodies of " + std::to_string(vertices) +
                 " vertices, the scene " + std::to_string(model.bodies.size()) + " of " +
                 std::to_string(model.vertex_count()));
  }
  if (bytes.size() - kHeaderBytes != payload_size) {
    throw refuse("truncated: the state has " + std::to_string(bytes.size() - kHeaderBytes) + " of its " +
                 std::to_string(payload_size) + " bytes");
  }
  const std::string_view payload(bytes.data() + kHeaderBytes, payload_size);
  if (payload_checksum != XXH3_64bits(payload.data(), payload.size())) throw refuse("corrupt state (checksum)");
  try {
    return sim::decode_state(payload, model);
  } catch (const softbody::InputError& e) {
    throw refuse(e.what());
  }
}

void write_manifest(const std::filesystem::path& dir, const CacheManifest& manifest) {
  nlohmann::json document = {{"format", kStateCacheFormat}, {"scene_hash", hex(manifest.scene_hash)},
                             {"every", manifest.every},     {"last_frame", manifest.last_frame},
                             {"fps", manifest.fps},         {"complete", manifest.complete}};
  write_file_atomically(dir / "cache.json", document.dump(2) + "\n");
}

CacheManifest read_manifest(const std::filesystem::path& dir, std::uint64_t scene_hash) {
  const std::filesystem::path path = dir / "cache.json";
  const std::string text = read_whole_file(path);
  if (text.empty())
    throw softbody::InputError(path.string() +
                               ": missing (not a state cache folder: make one with "
                               "softbody simulate SCENE --cache DIR)");
  CacheManifest manifest;
  try {
    const nlohmann::json document = nlohmann::json::parse(text);
    if (document.at("format").get<std::uint32_t>() != kStateCacheFormat) {
      throw softbody::InputError(path.string() + ": another cache format (simulate the scene again with --cache)");
    }
    manifest.scene_hash = std::stoull(document.at("scene_hash").get<std::string>(), nullptr, 16);
    manifest.every = document.at("every").get<int>();
    manifest.last_frame = document.at("last_frame").get<int>();
    manifest.fps = document.at("fps").get<int>();
    manifest.complete = document.at("complete").get<bool>();
  } catch (const softbody::InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw softbody::InputError(path.string() + ": unreadable manifest (" + e.what() + ")");
  }
  if (manifest.every < 1 || manifest.last_frame < 0)
    throw softbody::InputError(path.string() + ": unreadable manifest");
  if (manifest.scene_hash != scene_hash) {
    throw softbody::InputError(path.string() +
                               ": a cache of another scene or of another build of softbody (scene hash " +
                               hex(manifest.scene_hash) + ", this scene's " + hex(scene_hash) +
                               "): simulate this scene with --cache " + dir.string());
  }
  return manifest;
}

int cached_frame_at_or_before(const CacheManifest& manifest, int frame) {
  if (frame >= manifest.last_frame) return manifest.last_frame;
  return frame / manifest.every * manifest.every;
}

StateCacheSink::StateCacheSink(std::filesystem::path dir, std::uint64_t scene_hash, int every, int last_frame, int fps,
                               bool keep)
    : dir_(std::move(dir)) {
  manifest_.scene_hash = scene_hash;
  manifest_.every = every;
  manifest_.last_frame = last_frame;
  manifest_.fps = fps;
  std::filesystem::create_directories(dir_);
  // A new cache replaces whatever states an earlier run left in the folder.
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
    if (keep) break;
    const std::string name = entry.path().filename().string();
    if (name.rfind("state_", 0) == 0 && entry.path().extension() == ".bin") std::filesystem::remove(entry.path());
  }
  write_manifest(dir_, manifest_);
}

void StateCacheSink::capture(int index, double /*time_s*/, const sim::World& world) {
  captured_index_ = index;
  captured_.clear();
  if (index % manifest_.every != 0 && index != manifest_.last_frame) return;
  captured_ = cached_state_file(index, manifest_.scene_hash, world.model, world.state);
}

void StateCacheSink::deliver() {
  if (captured_.empty()) return;
  write_file_atomically(cached_state_path(dir_, captured_index_), captured_);
  bytes_per_state_ = captured_.size();
  ++states_written_;
}

void StateCacheSink::finish(bool complete) {
  manifest_.complete = complete;
  write_manifest(dir_, manifest_);
}

}  // namespace output
