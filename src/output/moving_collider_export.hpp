// The keyframed colliders written as they move, so that an import shows them where the bodies met them:
// - beside a mesh sequence, per frame: DIR/collider_<N>_%04d.obj (or .ply), numbered like the body frames;
// - beside point caches: DIR/collider_<N>.obj (its surface at the first frame handed over) and DIR/collider_<N>.pc2
//   (or .mdd) of its vertices at every frame (a shape's tessellation keeps its vertex count as it moves).
// N is the collider's index in the scene's "colliders"; static colliders are written once (output/collider_export.hpp).
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frames/frame_sink.hpp"
#include "output/point_cache.hpp"
#include "sim/model/settings.hpp"

namespace output {

// The indices of the keyframed colliders among `colliders`.
std::vector<std::size_t> moving_colliders(std::span<const sim::Collider> colliders);

// The file names of collider `index`'s frames: "collider_<N>_%04d.obj" (or .ply, `extension`).
std::string collider_frame_pattern(std::size_t index, const std::string& extension);

// Removes every collider frame file in `dir` (collider_<N>_%04d with `extension`, whatever N and the frame number):
// an earlier run's, before a whole new run writes its own. Returns how many.
int remove_collider_frames(const std::filesystem::path& dir, const std::string& extension);

class ColliderFrameExporter final : public frames::FrameSink {
 public:
  // Writes each keyframed collider of `colliders` at each frame's time to DIR/collider_<N>_%04d.obj (or .ply,
  // `extension`), each file whole (temporary name, then renamed).
  ColliderFrameExporter(std::filesystem::path dir, std::span<const sim::Collider> colliders, std::string extension);
  void on_frame(int index, double time_s, const sim::World& world) override;
  void finish(bool complete) override;

  // The files of frame `index`, one per keyframed collider (none when every collider is static).
  std::vector<std::filesystem::path> frame_paths(int index) const;
  // Calls `stored(path, bytes)` after each file is in place.
  void after_each_file(std::function<void(const std::filesystem::path&, std::string_view)> stored);

 private:
  std::filesystem::path dir_;
  std::vector<std::size_t> moving_;
  std::string extension_;
  std::function<void(const std::filesystem::path&, std::string_view)> stored_;
};

class ColliderCacheExporter final : public frames::FrameSink {
 public:
  // Gathers each keyframed collider's vertices at every frame handed over (one after another) and writes, at
  // finish(), DIR/collider_<N>.obj and DIR/collider_<N>.pc2 (or .mdd), each file whole, as PointCacheExporter does
  // for a body.
  ColliderCacheExporter(std::filesystem::path dir, std::span<const sim::Collider> colliders, PointCacheFormat format);
  void on_frame(int index, double time_s, const sim::World& world) override;
  void finish(bool complete) override;

  const std::vector<std::size_t>& moving() const { return moving_; }
  std::filesystem::path mesh_path(std::size_t collider) const;
  std::filesystem::path cache_path(std::size_t collider) const;

 private:
  std::filesystem::path dir_;
  std::vector<std::size_t> moving_;
  PointCacheFormat format_;
  int first_frame_ = -1;
  int last_frame_ = -1;
  std::vector<std::string> meshes_obj_;  // per moving collider, from the first frame
  std::vector<PointSamples> samples_;    // per moving collider
};

}  // namespace output
