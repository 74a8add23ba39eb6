// The state cache: the simulation's State at every Nth frame, one binary file each, so that frames can be
// rendered later, elsewhere and in parallel without simulating again, and a killed run can continue.
//
//   DIR/cache.json          the manifest: format, scene hash, every N, the run's last frame, complete or not
//   DIR/state_000120.bin    frame 120: a 96-byte header, then the State (sim/model/state_codec.hpp)
//
// Header (little-endian): magic "SOFTBODY STATE\n\0" (16 bytes), u32 file format, u32 state codec version,
// u64 scene hash (setup/scene_hash.hpp), i32 frame, u32 bodies, f64 time [s], char[16] integrator name,
// u64 vertices, u64 payload bytes, u64 XXH3-64 of the payload, u64 XXH3-64 of the 88 header bytes before
// it. Each file is written under a temporary name and renamed, so a killed run leaves only whole files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "frames/capturing_sink.hpp"
#include "sim/model/model.hpp"
#include "sim/model/state.hpp"

namespace output {

inline constexpr std::uint32_t kStateCacheFormat = 1;

struct CacheManifest {
  std::uint64_t scene_hash = 0;
  int every = 1;       // a state for every frame index divisible by this, and for the last frame
  int last_frame = 0;  // the run's last frame (frame 0 is the initial state)
  int fps = 30;
  bool complete = false;  // the run reached its last frame
};

std::filesystem::path cached_state_path(const std::filesystem::path& dir, int frame);

// The file of frame `frame`'s state: header and encoded state.
std::string cached_state_file(int frame, std::uint64_t scene_hash, const sim::Model& model, const sim::State& state);

// Writes frame `frame`'s state atomically. Throws std::runtime_error naming the file on I/O failure.
void write_cached_state(const std::filesystem::path& dir, int frame, std::uint64_t scene_hash, const sim::Model& model,
                        const sim::State& state);

// True when the file for `frame` exists (whatever its content).
bool has_cached_state(const std::filesystem::path& dir, int frame);

// Reads and checks frame `frame`'s state: magic, versions, checksums, the scene hash (a cache of another
// scene), the frame number, and the model's bodies and vertices. Throws softbody::InputError naming the
// file and what is wrong (missing, truncated, corrupt, another scene).
sim::State read_cached_state(const std::filesystem::path& dir, int frame, std::uint64_t scene_hash,
                             const sim::Model& model);

void write_manifest(const std::filesystem::path& dir, const CacheManifest& manifest);
// Reads DIR/cache.json; refuses (softbody::InputError) a missing or unreadable manifest, another format, or
// another scene's hash.
CacheManifest read_manifest(const std::filesystem::path& dir, std::uint64_t scene_hash);

// The cached frame a run can start from to reach `frame`: the largest frame <= `frame` that the manifest's
// spacing caches (a multiple of `every`, or the last frame).
int cached_frame_at_or_before(const CacheManifest& manifest, int frame);

// A frame sink that caches the state of every `every`th frame and the last one, and keeps the manifest.
// A new cache starts by removing the states an earlier run left in the folder; a continued one (a resumed
// run: `keep` true) keeps them.
class StateCacheSink final : public frames::CapturingFrameSink {
 public:
  StateCacheSink(std::filesystem::path dir, std::uint64_t scene_hash, int every, int last_frame, int fps,
                 bool keep = false);
  // Encodes the state (while the world is at rest); deliver() writes it.
  void capture(int index, double time_s, const sim::World& world) override;
  void deliver() override;
  // Marks the manifest complete when the run reached its last frame.
  void finish(bool complete) override;

  // Bytes written per cached state (the last one), for the summary.
  std::size_t bytes_per_state() const { return bytes_per_state_; }
  int states_written() const { return states_written_; }

 private:
  std::filesystem::path dir_;
  CacheManifest manifest_;
  std::string captured_;  // the file of the captured frame ("" when it is not cached)
  int captured_index_ = 0;
  std::size_t bytes_per_state_ = 0;
  int states_written_ = 0;
};

}  // namespace output
