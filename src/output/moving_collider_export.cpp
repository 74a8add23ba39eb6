// The keyframed colliders' surfaces at every frame: a mesh sequence per collider, or a point cache.
#include "output/moving_collider_export.hpp"

#include <cstdio>
#include <stdexcept>

#include "core/profile.hpp"
#include "output/atomic_file.hpp"
#include "output/collider_export.hpp"
#include "output/frame_pattern.hpp"
#include "output/mesh_file_writer.hpp"

namespace output {
namespace {

// The comment line of a collider's file at time t.
std::string collider_comment(std::size_t index, double time_s) {
  char text[128];
  std::snprintf(text, sizeof text, "softbody collider %zu at t = %.9g s (keyframed, world coordinates, m)", index,
                time_s);
  return text;
}

// The surface of keyframed collider `index` of `world` at time t.
mesh::TriMesh moving_surface(const sim::World& world, std::size_t index, double time_s) {
  return collider_surface(sim::collider_at(world.model.colliders[index], time_s));
}

}  // namespace

std::vector<std::size_t> moving_colliders(std::span<const sim::Collider> colliders) {
  std::vector<std::size_t> moving;
  for (std::size_t i = 0; i < colliders.size(); ++i) {
    if (colliders[i].motion.moving()) moving.push_back(i);
  }
  return moving;
}

std::string collider_frame_pattern(std::size_t index, const std::string& extension) {
  return "collider_" + std::to_string(index) + "_%04d" + extension;
}

int remove_collider_frames(const std::filesystem::path& dir, const std::string& extension) {
  const std::string prefix = "collider_";
  std::error_code ec;
  std::vector<std::filesystem::path> frames;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    std::size_t end = prefix.size();
    while (end < name.size() && end - prefix.size() < 9 && name[end] >= '0' && name[end] <= '9') ++end;
    if (end == prefix.size()) continue;
    const std::size_t index = std::stoul(name.substr(prefix.size(), end - prefix.size()));
    if (frame_index_of(collider_frame_pattern(index, extension), name) && entry.is_regular_file(ec))
      frames.push_back(entry.path());
  }
  int removed = 0;
  for (const std::filesystem::path& frame : frames) removed += std::filesystem::remove(frame, ec) ? 1 : 0;
  return removed;
}

ColliderFrameExporter::ColliderFrameExporter(std::filesystem::path dir, std::span<const sim::Collider> colliders,
                                             std::string extension)
    : dir_(std::move(dir)), moving_(moving_colliders(colliders)), extension_(std::move(extension)) {
  std::filesystem::create_directories(dir_);
}

std::vector<std::filesystem::path> ColliderFrameExporter::frame_paths(int index) const {
  std::vector<std::filesystem::path> paths;
  for (const std::size_t collider : moving_)
    paths.push_back(dir_ / frame_file_name(collider_frame_pattern(collider, extension_), index));
  return paths;
}

void ColliderFrameExporter::on_frame(int index, double time_s, const sim::World& world) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::mesh_write);
  const std::vector<std::filesystem::path> paths = frame_paths(index);
  for (std::size_t m = 0; m < moving_.size(); ++m) {
    const mesh::TriMesh surface = moving_surface(world, moving_[m], time_s);
    const std::string comment = collider_comment(moving_[m], time_s);
    const std::string bytes =
        extension_ == ".ply" ? trimesh_to_ply(surface, comment) : trimesh_to_obj(surface, comment);
    write_file_atomically(paths[m], bytes);
    if (stored_) stored_(paths[m], bytes);
  }
}

void ColliderFrameExporter::after_each_file(
    std::function<void(const std::filesystem::path&, std::string_view)> stored) {
  stored_ = std::move(stored);
}

void ColliderFrameExporter::finish(bool /*complete*/) {}

ColliderCacheExporter::ColliderCacheExporter(std::filesystem::path dir, std::span<const sim::Collider> colliders,
                                             PointCacheFormat format)
    : dir_(std::move(dir)), moving_(moving_colliders(colliders)), format_(format) {
  std::filesystem::create_directories(dir_);
}

std::filesystem::path ColliderCacheExporter::mesh_path(std::size_t collider) const {
  return collider_path(dir_, collider, ".obj");
}

std::filesystem::path ColliderCacheExporter::cache_path(std::size_t collider) const {
  return collider_path(dir_, collider, format_ == PointCacheFormat::Pc2 ? ".pc2" : ".mdd");
}

void ColliderCacheExporter::on_frame(int index, double time_s, const sim::World& world) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::mesh_write);
  if (first_frame_ >= 0 && index != last_frame_ + 1) {
    throw std::logic_error("a point cache needs frames one after another, got " + std::to_string(index) + " after " +
                           std::to_string(last_frame_));
  }
  const bool first = first_frame_ < 0;
  if (first) first_frame_ = index;
  last_frame_ = index;
  for (std::size_t m = 0; m < moving_.size(); ++m) {
    const mesh::TriMesh surface = moving_surface(world, moving_[m], time_s);
    if (first) {
      meshes_obj_.push_back(trimesh_to_obj(surface, collider_comment(moving_[m], time_s)));
      samples_.push_back({static_cast<int>(surface.vertices.size()), {}, {}});
    }
    PointSamples& samples = samples_[m];
    for (const softbody::Vec3& p : surface.vertices) {
      for (int axis = 0; axis < 3; ++axis) samples.xyz.push_back(static_cast<float>(p[axis]));
    }
    samples.times_s.push_back(static_cast<float>(time_s));
  }
}

// Also after a stopped run (diverged): the frames before are valid, and the cache says how many it holds.
void ColliderCacheExporter::finish(bool /*complete*/) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::mesh_write);
  for (std::size_t m = 0; m < samples_.size(); ++m) {
    write_file_atomically(mesh_path(moving_[m]), meshes_obj_[m]);
    write_file_atomically(cache_path(moving_[m]), format_ == PointCacheFormat::Pc2
                                                      ? encode_pc2(samples_[m], static_cast<float>(first_frame_), 1.0f)
                                                      : encode_mdd(samples_[m]));
  }
}

}  // namespace output
