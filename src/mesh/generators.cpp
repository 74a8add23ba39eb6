// Built-in mesh generators: icosphere and subdivided cube.
#include "mesh/generators.hpp"

#include <cmath>
#include <map>
#include <optional>

#include "core/errors.hpp"
#include "mesh/weld.hpp"

namespace mesh {
namespace {

constexpr int kMaxIcosphereLevel = 7;  // 163842 vertices
constexpr int kMaxCubeDivisions = 128;

struct GeneratorSpec {
  std::string name;
  int argument;
};

std::optional<int> parse_int(const std::string& text) {
  if (text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  return std::stoi(text);
}

std::optional<GeneratorSpec> split_spec(const std::string& spec) {
  const std::size_t colon = spec.find(':');
  if (colon == std::string::npos) return std::nullopt;
  const std::string name = spec.substr(0, colon);
  if (name != "icosphere" && name != "cube") return std::nullopt;
  const std::optional<int> argument = parse_int(spec.substr(colon + 1));
  return GeneratorSpec{name, argument.value_or(-1)};
}

// Index of the midpoint of edge (a, b), created on first use and projected onto the unit sphere.
int midpoint(TriMesh& mesh, std::map<std::pair<int, int>, int>& cache, int a, int b) {
  const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  mesh.vertices.push_back((mesh.vertices[a] + mesh.vertices[b]).normalized());
  const int index = static_cast<int>(mesh.vertices.size()) - 1;
  cache.emplace(key, index);
  return index;
}

}  // namespace

bool names_generator(const std::string& spec) {
  const std::size_t colon = spec.find(':');
  if (colon == std::string::npos) return false;
  const std::string name = spec.substr(0, colon);
  return name == "icosphere" || name == "cube";
}

std::string generator_spec_error(const std::string& spec) {
  const std::optional<GeneratorSpec> parsed = split_spec(spec);
  if (!parsed) return "expected a generator icosphere:L or cube:N, got \"" + spec + "\"";
  if (parsed->name == "icosphere" && (parsed->argument < 0 || parsed->argument > kMaxIcosphereLevel)) {
    return "expected icosphere:L with L an integer in 0.." + std::to_string(kMaxIcosphereLevel) + ", got \"" + spec + "\"";
  }
  if (parsed->name == "cube" && (parsed->argument < 1 || parsed->argument > kMaxCubeDivisions)) {
    return "expected cube:N with N an integer in 1.." + std::to_string(kMaxCubeDivisions) + ", got \"" + spec + "\"";
  }
  return "";
}

TriMesh generate(const std::string& spec) {
  if (const std::string error = generator_spec_error(spec); !error.empty()) throw softbody::InputError(error);
  const GeneratorSpec parsed = *split_spec(spec);
  return parsed.name == "icosphere" ? icosphere(parsed.argument) : cube(parsed.argument);
}

TriMesh icosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;  // golden ratio: icosahedron vertices (0, ±1, ±t) cycled
  TriMesh mesh;
  for (const Vec3& v : {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0),
                        Vec3(0, -1, t), Vec3(0, 1, t), Vec3(0, -1, -t), Vec3(0, 1, -t),
                        Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)}) {
    mesh.vertices.push_back(v.normalized());
  }
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> cache;
    std::vector<Triangle> finer;
    finer.reserve(mesh.triangles.size() * 4);
    for (const Triangle& f : mesh.triangles) {
      const int ab = midpoint(mesh, cache, f[0], f[1]);
      const int bc = midpoint(mesh, cache, f[1], f[2]);
      const int ca = midpoint(mesh, cache, f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    mesh.triangles = std::move(finer);
  }
  return mesh;
}

TriMesh cube(int divisions) {
  TriMesh mesh;
  const int n = divisions;
  // Each face: an origin corner and two in-plane axes whose cross product points outward.
  struct Face {
    Vec3 origin, u, v;
  };
  const Face faces[6] = {
      {{0.5, -0.5, -0.5}, {0, 1, 0}, {0, 0, 1}},  {{-0.5, -0.5, -0.5}, {0, 0, 1}, {0, 1, 0}},
      {{-0.5, 0.5, -0.5}, {0, 0, 1}, {1, 0, 0}},  {{-0.5, -0.5, -0.5}, {1, 0, 0}, {0, 0, 1}},
      {{-0.5, -0.5, 0.5}, {1, 0, 0}, {0, 1, 0}},  {{-0.5, -0.5, -0.5}, {0, 1, 0}, {1, 0, 0}},
  };
  for (const Face& face : faces) {
    const int base = static_cast<int>(mesh.vertices.size());
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        mesh.vertices.push_back(face.origin + face.u * (double(i) / n) + face.v * (double(j) / n));
      }
    }
    auto at = [&](int i, int j) { return base + i * (n + 1) + j; };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return weld(mesh);  // faces share their border vertices
}

}  // namespace mesh
