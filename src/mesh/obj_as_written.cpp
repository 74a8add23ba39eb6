// The OBJ reader that keeps the file's vertex order (for point caches).
#include "mesh/obj_as_written.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "core/file_kind.hpp"

namespace mesh {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& file, long long line, const std::string& what) {
  throw softbody::InputError(file.string() + ":" + std::to_string(line) + ": " + what);
}

// The vertex a face corner names ("7", "7/2", "7//3", "-1/2/3"), as a 0-based index into the `count` so far.
int corner_index(const std::string& token, std::size_t count, const std::filesystem::path& file, long long line) {
  const std::string number = token.substr(0, token.find('/'));
  char* end = nullptr;
  const long long written = std::strtoll(number.c_str(), &end, 10);
  if (number.empty() || *end != '\0')
    refuse(file, line, "expected a vertex index in the face corner \"" + token + "\"");
  const long long index = written < 0 ? static_cast<long long>(count) + written : written - 1;
  if (written == 0 || index < 0 || index >= static_cast<long long>(count)) {
    refuse(file, line,
           "face corner " + number + " names no vertex (" + std::to_string(count) + " vertices so far, from 1)");
  }
  return static_cast<int>(index);
}

Vec3 read_vertex(std::istringstream& words, const std::filesystem::path& file, long long line) {
  Vec3 p;
  for (int axis = 0; axis < 3; ++axis) {
    std::string word;
    words >> word;
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (word.empty() || *end != '\0' || !std::isfinite(value) || std::abs(value) > kMaxMeshCoordinate)
      refuse(file, line, "expected 3 finite coordinates within 1e12 after \"v\"");
    p[axis] = value;
  }
  return p;
}

}  // namespace

TriMesh read_obj_as_written(const std::filesystem::path& file, const MeshLimits& limits) {
  softbody::require_regular_file(file, limits.max_file_bytes, "mesh file",
                                 "raise it with the scene key limits.max_file_mb");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw softbody::InputError(file.string() + ": cannot open the mesh file");
  TriMesh mesh;
  std::string text;
  long long line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream words(text);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      if (static_cast<long long>(mesh.vertices.size()) >= limits.max_vertices)
        refuse(file, line, "more than " + std::to_string(limits.max_vertices) + " vertices (limits.max_vertices)");
      mesh.vertices.push_back(read_vertex(words, file, line));
    } else if (kind == "f") {
      std::vector<int> corners;
      for (std::string token; words >> token;) corners.push_back(corner_index(token, mesh.vertices.size(), file, line));
      if (corners.size() < 3) refuse(file, line, "expected a face of at least 3 corners");
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        if (static_cast<long long>(mesh.triangles.size()) >= limits.max_triangles)
          refuse(file, line, "more than " + std::to_string(limits.max_triangles) + " triangles (limits.max_triangles)");
        mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
      }
    }
  }
  if (in.bad()) throw softbody::InputError(file.string() + ": cannot read the mesh file");
  if (mesh.triangles.empty()) throw softbody::InputError(file.string() + ": holds no face (\"f\" lines)");
  return mesh;
}

}  // namespace mesh
