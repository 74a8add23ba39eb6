// Built-in mesh generators: icosphere, subdivided cube, torus, capsule, tube.
#include "mesh/generators.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <vector>

#include "core/errors.hpp"
#include "mesh/weld.hpp"

namespace mesh {
namespace {

// A generator: its name, its integer arguments with their ranges, and how to build it.
struct Generator {
  const char* name;
  const char* usage;                        // e.g. "icosphere:L with L in 0..7"
  std::vector<std::pair<int, int>> ranges;  // inclusive range of each argument
  TriMesh (*build)(const std::vector<int>& arguments);
};

const std::vector<Generator>& generators() {
  static const std::vector<Generator> table = {
      {"icosphere",
       "icosphere:L with L an integer in 0..7",
       {{0, 7}},
       [](const std::vector<int>& a) { return icosphere(a[0]); }},
      {"cube", "cube:N with N an integer in 1..128", {{1, 128}}, [](const std::vector<int>& a) { return cube(a[0]); }},
      {"torus",
       "torus:M,N with M (around the ring) in 3..512 and N (around the tube) in 3..256",
       {{3, 512}, {3, 256}},
       [](const std::vector<int>& a) { return torus(a[0], a[1]); }},
      {"capsule",
       "capsule:N with N (segments around) an integer in 4..256",
       {{4, 256}},
       [](const std::vector<int>& a) { return capsule(a[0]); }},
      {"tube",
       "tube:N,L with N (segments around) in 4..256 and L (the cylinder's length in m) in 1..100",
       {{4, 256}, {1, 100}},
       [](const std::vector<int>& a) { return tube(a[0], a[1]); }},
  };
  return table;
}

const Generator* find_generator(const std::string& spec) {
  const std::string name = spec.substr(0, spec.find(':'));
  for (const Generator& g : generators()) {
    if (name == g.name) return &g;
  }
  return nullptr;
}

// The comma-separated integer arguments after the colon; nullopt when they do not fit `generator`.
std::optional<std::vector<int>> parse_arguments(const Generator& generator, const std::string& spec) {
  std::vector<int> arguments;
  std::string text = spec.substr(spec.find(':') + 1) + ",";
  for (std::size_t start = 0, comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1) {
    const std::string part = text.substr(start, comma - start);
    if (part.empty() || part.size() > 6 || part.find_first_not_of("0123456789") != std::string::npos)
      return std::nullopt;
    arguments.push_back(std::stoi(part));
  }
  if (arguments.size() != generator.ranges.size()) return std::nullopt;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    if (arguments[i] < generator.ranges[i].first || arguments[i] > generator.ranges[i].second) return std::nullopt;
  }
  return arguments;
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
  return spec.find(':') != std::string::npos && find_generator(spec) != nullptr;
}

std::string generator_spec_error(const std::string& spec) {
  const Generator* generator = find_generator(spec);
  if (generator == nullptr || spec.find(':') == std::string::npos) {
    return "expected a generator (icosphere:L, cube:N, torus:M,N, capsule:N, tube:N,L), got \"" + spec + "\"";
  }
  if (!parse_arguments(*generator, spec)) return std::string("expected ") + generator->usage + ", got \"" + spec + "\"";
  return "";
}

TriMesh generate(const std::string& spec) {
  if (const std::string error = generator_spec_error(spec); !error.empty()) throw softbody::InputError(error);
  const Generator& generator = *find_generator(spec);
  return generator.build(*parse_arguments(generator, spec));
}

TriMesh icosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;  // golden ratio: icosahedron vertices (0, ±1, ±t) cycled
  TriMesh mesh;
  for (const Vec3& v :
       {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0), Vec3(0, -1, t), Vec3(0, 1, t), Vec3(0, -1, -t),
        Vec3(0, 1, -t), Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)}) {
    mesh.vertices.push_back(v.normalized());
  }
  mesh.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
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
      {{0.5, -0.5, -0.5}, {0, 1, 0}, {0, 0, 1}}, {{-0.5, -0.5, -0.5}, {0, 0, 1}, {0, 1, 0}},
      {{-0.5, 0.5, -0.5}, {0, 0, 1}, {1, 0, 0}}, {{-0.5, -0.5, -0.5}, {1, 0, 0}, {0, 0, 1}},
      {{-0.5, -0.5, 0.5}, {1, 0, 0}, {0, 1, 0}}, {{-0.5, -0.5, -0.5}, {0, 1, 0}, {1, 0, 0}},
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

namespace mesh {
namespace {

// Index of vertex `j` (wrapping) on ring `i` of a grid of rings with `per_ring` vertices each.
int ring_vertex(int i, int j, int per_ring) { return i * per_ring + (j % per_ring); }

// Joins ring i to ring i + 1 with two triangles per segment, wound so that the outside is on the left
// when both rings run the same way.
void join_rings(TriMesh& mesh, int i, int next, int per_ring) {
  for (int j = 0; j < per_ring; ++j) {
    const int a = ring_vertex(i, j, per_ring), b = ring_vertex(i, j + 1, per_ring);
    const int c = ring_vertex(next, j, per_ring), d = ring_vertex(next, j + 1, per_ring);
    mesh.triangles.push_back({a, c, b});
    mesh.triangles.push_back({b, c, d});
  }
}

}  // namespace

TriMesh torus(int ring_segments, int tube_segments) {
  constexpr double kMajorRadius = 1.0, kMinorRadius = 0.4;
  TriMesh mesh;
  for (int i = 0; i < ring_segments; ++i) {
    const double u = 2 * std::numbers::pi * i / ring_segments;
    for (int j = 0; j < tube_segments; ++j) {
      const double w = 2 * std::numbers::pi * j / tube_segments;
      const double r = kMajorRadius + kMinorRadius * std::cos(w);
      mesh.vertices.emplace_back(r * std::cos(u), kMinorRadius * std::sin(w), -r * std::sin(u));
    }
  }
  for (int i = 0; i < ring_segments; ++i) join_rings(mesh, i, (i + 1) % ring_segments, tube_segments);
  return mesh;
}

namespace {

// Radius 0.5, a cylinder of length 2 half_length along y between two hemispheres, centred at the origin, with
// `inner_rings` evenly spaced rings along the cylinder between the hemispheres' equators.
TriMesh capsule_along_y(int segments, double half_length, int inner_rings) {
  constexpr double kRadius = 0.5;
  const int latitude_steps = std::max(2, segments / 4);  // per hemisphere, pole excluded
  TriMesh mesh;
  mesh.vertices.emplace_back(0.0, half_length + kRadius, 0.0);  // top pole
  std::vector<std::pair<double, double>> rings;                 // (y, ring radius) from top to bottom
  for (int k = 1; k <= latitude_steps; ++k) {
    const double polar = 0.5 * std::numbers::pi * k / latitude_steps;
    rings.emplace_back(half_length + kRadius * std::cos(polar), kRadius * std::sin(polar));
  }
  for (int k = 1; k <= inner_rings; ++k) rings.emplace_back(half_length * (1.0 - 2.0 * k / (inner_rings + 1)), kRadius);
  for (int k = latitude_steps; k >= 1; --k) {
    const double polar = 0.5 * std::numbers::pi * k / latitude_steps;
    rings.emplace_back(-half_length - kRadius * std::cos(polar), kRadius * std::sin(polar));
  }
  for (const auto& [y, radius] : rings) {
    for (int j = 0; j < segments; ++j) {
      const double angle = 2 * std::numbers::pi * j / segments;
      mesh.vertices.emplace_back(radius * std::cos(angle), y, -radius * std::sin(angle));
    }
  }
  const int ring_count = static_cast<int>(rings.size());
  const int bottom = static_cast<int>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0, -half_length - kRadius, 0.0);  // bottom pole
  auto ring = [&](int i, int j) { return 1 + ring_vertex(i, j, segments); };
  for (int j = 0; j < segments; ++j) mesh.triangles.push_back({0, ring(0, j), ring(0, j + 1)});
  for (int i = 0; i + 1 < ring_count; ++i) {
    for (int j = 0; j < segments; ++j) {
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  }
  for (int j = 0; j < segments; ++j)
    mesh.triangles.push_back({bottom, ring(ring_count - 1, j + 1), ring(ring_count - 1, j)});
  return mesh;
}

}  // namespace

TriMesh capsule(int segments) { return capsule_along_y(segments, 0.5, 0); }

TriMesh tube(int segments, int length) {
  // Rings along the cylinder about as far apart as the vertices around it (2π r / N): near-square quads.
  const double spacing = std::numbers::pi / segments;
  const int inner_rings = std::max(0, static_cast<int>(std::lround(length / spacing)) - 1);
  return capsule_along_y(segments, 0.5 * length, inner_rings);
}

}  // namespace mesh
