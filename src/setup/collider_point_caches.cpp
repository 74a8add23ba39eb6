// A point-cached mesh collider: the mesh as written, the PC2 samples, the times in seconds, the weld.
#include "setup/collider_point_caches.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "core/errors.hpp"
#include "core/one_line.hpp"
#include "mesh/generators.hpp"
#include "mesh/obj_as_written.hpp"
#include "mesh/pc2_file.hpp"
#include "output/frame_pattern.hpp"
#include "sim/contact/collider_mesh.hpp"
#include "sim/contact/collider_point_cache.hpp"

namespace setup {
namespace {

using softbody::Vec3;

// The mesh with its vertices in the order the cache's points take.
mesh::TriMesh read_as_written(const scene::ColliderMeshSource& source, const mesh::MeshLimits& limits,
                              const std::string& key) {
  if (source.mesh_file.empty()) return mesh::generate(source.mesh);
  std::string extension = source.mesh_file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".obj") {
    throw softbody::InputError(key + ": a point-cached mesh must be an OBJ file or a generator, not " +
                               softbody::one_line(source.mesh_file.string()) +
                               " (the cache's points follow the order of an OBJ's \"v\" lines)");
  }
  return mesh::read_obj_as_written(source.mesh_file, limits);
}

// Vertices at exactly the same place merged: `first_of[v]` is the first vertex at v's place (a file's seams split
// them; merged, a closed mesh is solid). Returns the merged mesh, its vertex w being the file's `kept[w]`.
mesh::TriMesh weld_exact(const mesh::TriMesh& m, std::vector<std::size_t>& kept) {
  std::map<std::tuple<double, double, double>, int> index_at;
  std::vector<int> merged(m.vertices.size());
  mesh::TriMesh out;
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    const Vec3& p = m.vertices[v];
    const auto [it, added] = index_at.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(out.vertices.size()));
    if (added) {
      out.vertices.push_back(p);
      kept.push_back(v);
    }
    merged[v] = it->second;
  }
  for (const softbody::Triangle& t : m.triangles) {
    out.triangles.push_back({merged[static_cast<std::size_t>(t[0])], merged[static_cast<std::size_t>(t[1])],
                             merged[static_cast<std::size_t>(t[2])]});
  }
  return out;
}

// The cache's samples as written (one position per vertex of the mesh file) and the frame number of each.
struct WrittenSamples {
  std::vector<std::vector<Vec3>> positions;
  std::vector<double> frames;
};

// The files a sequence's pattern names in its folder, by frame number.
std::vector<std::pair<int, std::filesystem::path>> sequence_files(const std::filesystem::path& pattern_path) {
  const std::string pattern = pattern_path.filename().string();
  const std::filesystem::path folder = pattern_path.parent_path().empty() ? "." : pattern_path.parent_path();
  std::vector<std::pair<int, std::filesystem::path>> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::optional<int> frame = output::frame_index_of(pattern, entry.path().filename().string());
    if (frame && entry.is_regular_file(ec)) files.emplace_back(*frame, entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

WrittenSamples read_pc2_samples(const std::filesystem::path& file, const mesh::MeshLimits& limits) {
  mesh::Pc2Cache pc2 = mesh::read_pc2_file(file, limits);
  WrittenSamples written;
  for (std::size_t s = 0; s < pc2.samples.size(); ++s)
    written.frames.push_back(pc2.start_frame + static_cast<double>(s) * pc2.frames_per_sample);
  written.positions = std::move(pc2.samples);
  return written;
}

// Every file of the sequence, each with the first's triangles; at most as many positions in all as a PC2 file
// within the size limit holds (12 bytes each).
WrittenSamples read_sequence_samples(const std::filesystem::path& pattern_path, const mesh::MeshLimits& limits) {
  const std::vector<std::pair<int, std::filesystem::path>> files = sequence_files(pattern_path);
  if (files.empty()) {
    throw softbody::InputError("no file in " + softbody::one_line(pattern_path.parent_path().string()) +
                               " is named by the numbered sequence " +
                               softbody::one_line(pattern_path.filename().string()));
  }
  WrittenSamples written;
  mesh::TriMesh first;
  std::uintmax_t positions = 0;
  for (const auto& [frame, file] : files) {
    mesh::TriMesh m = mesh::read_obj_as_written(file, limits);
    if (written.positions.empty()) {
      first.triangles = m.triangles;
      first.vertices.resize(m.vertices.size());
    } else if (m.vertices.size() != first.vertices.size() || m.triangles != first.triangles) {
      throw softbody::InputError(softbody::one_line(file.string()) + ": has " + std::to_string(m.vertices.size()) +
                                 " vertices and " + std::to_string(m.triangles.size()) +
                                 " triangles, expected the same vertices and triangles as the sequence's first file " +
                                 softbody::one_line(files.front().second.string()) + " (" +
                                 std::to_string(first.vertices.size()) + " and " +
                                 std::to_string(first.triangles.size()) + ", the same corners)");
    }
    positions += m.vertices.size();
    if (positions > limits.max_file_bytes / 12) {
      throw softbody::InputError(softbody::one_line(pattern_path.string()) + ": the sequence holds more than " +
                                 std::to_string(limits.max_file_bytes / 12) +
                                 " positions in all (raise it with the scene key limits.max_file_mb)");
    }
    written.frames.push_back(frame);
    written.positions.push_back(std::move(m.vertices));
  }
  return written;
}

}  // namespace

void load_collider_point_cache(const scene::Scene& scene, const scene::ColliderMeshSource& source,
                               sim::Collider& collider) {
  const std::string where = scene.source.string() + ": colliders." + std::to_string(source.collider);
  const std::string mesh_words = softbody::one_line(source.mesh_file.empty() ? source.mesh : source.mesh_file.string());
  const std::string cache_words = softbody::one_line(source.cache_file.string());
  mesh::TriMesh written;
  WrittenSamples cached;
  try {
    written = read_as_written(source, scene.limits, where + ".mesh");
  } catch (const softbody::InputError& e) {
    const std::string what = e.what();
    throw softbody::InputError(what.rfind(where, 0) == 0 ? what : where + ".mesh: " + what);
  }
  try {
    cached = source.cache_sequence ? read_sequence_samples(source.cache_file, scene.limits)
                                   : read_pc2_samples(source.cache_file, scene.limits);
  } catch (const softbody::InputError& e) {
    throw softbody::InputError(where + ".cache: " + e.what());
  }
  if (cached.positions.front().size() != written.vertices.size()) {
    throw softbody::InputError(where + ".cache: point cache " + cache_words + " holds " +
                               std::to_string(cached.positions.front().size()) + " points per sample, but the mesh " +
                               mesh_words + " has " + std::to_string(written.vertices.size()) +
                               " vertices (expected one point per vertex, in the mesh file's order)");
  }
  std::vector<std::size_t> kept;
  mesh::TriMesh welded = weld_exact(written, kept);
  for (Vec3& p : welded.vertices) p *= source.scale;
  // A sample's time: its frame / fps [s].
  const double fps = source.cache_fps > 0.0 ? source.cache_fps : static_cast<double>(scene.fps);
  std::vector<double> times;
  std::vector<std::vector<Vec3>> samples;
  for (std::size_t s = 0; s < cached.positions.size(); ++s) {
    times.push_back(cached.frames[s] / fps);
    std::vector<Vec3> positions;
    positions.reserve(kept.size());
    for (const std::size_t v : kept) positions.push_back(source.scale * cached.positions[s][v]);
    samples.push_back(std::move(positions));
  }
  try {
    const auto rest =
        sim::make_collider_mesh(std::move(welded.vertices), std::move(welded.triangles), source.thickness_m);
    collider.motion.cache = sim::make_collider_point_cache(rest, std::move(times), std::move(samples));
  } catch (const std::invalid_argument& e) {
    throw softbody::InputError(where + ": mesh " + mesh_words + " with point cache " + cache_words + ": " + e.what());
  }
  collider.geometry.mesh = collider.motion.cache->rest;
  collider.geometry.world_reach_m = sim::world_reach(collider.geometry);
}

std::vector<std::filesystem::path> point_cache_files(const scene::ColliderMeshSource& source) {
  if (source.cache_file.empty()) return {};
  if (!source.cache_sequence) return {source.cache_file};
  std::vector<std::filesystem::path> files;
  for (const auto& [frame, file] : sequence_files(source.cache_file)) files.push_back(file);
  return files;
}

}  // namespace setup
