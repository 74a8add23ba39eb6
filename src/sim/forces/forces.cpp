// Force loops: one pass each over vertices (gravity), edges (springs and dampers, fused) and faces (gas).
#include "sim/forces/forces.hpp"

#include <algorithm>
#include <cmath>

namespace sim {

void start_with_gravity(std::span<const double> mass_kg, const Vec3& g, std::span<Vec3> force) {
  for (std::size_t i = 0; i < force.size(); ++i) force[i] = mass_kg[i] * g;
}

namespace {

constexpr std::size_t kEdgeBlock = 64;  // edges per gather / compute / scatter round: scratch stays in L1

// One block of constraints, [first, first + n): the coefficient s_e with f_i = s_e d_e (and -s_e d_e on j).
template <bool kDamped>
void spring_damper_block(const DistanceConstraints& constraints, std::size_t first, std::size_t n,
                         std::span<const Vec3> x, std::span<const Vec3> v, std::span<Vec3> force) {
  const std::span<const std::array<int, 2>> edges = std::span(constraints.ends).subspan(first, n);
  const double* rest_length_m = constraints.rest_length_m.data() + first;
  const double* k = constraints.stiffness_N_per_m.data() + first;
  const double* c = constraints.damping_N_s_per_m.data() + first;
  alignas(64) double dx[kEdgeBlock], dy[kEdgeBlock], dz[kEdgeBlock], rate[kEdgeBlock], s[kEdgeBlock];
  for (std::size_t e = 0; e < n; ++e) {  // gather: d = x_i - x_j, and (v_i - v_j)·d
    const auto [i, j] = edges[e];
    const Vec3 d = x[i] - x[j];
    dx[e] = d.x();
    dy[e] = d.y();
    dz[e] = d.z();
    if constexpr (kDamped) rate[e] = (v[i] - v[j]).dot(d);
  }
  for (std::size_t e = 0; e < n; ++e) {  // no indirection: vectorised
    const double length_squared = dx[e] * dx[e] + dy[e] * dy[e] + dz[e] * dz[e];
    const double length = std::sqrt(length_squared);
    double numerator = -k[e] * (length - rest_length_m[e]) * length;
    if constexpr (kDamped) numerator -= c[e] * rate[e];
    // Coincident endpoints (L = 0, so d = 0 and the numerator is 0): divide by 1, no force.
    s[e] = numerator / (length_squared > 0.0 ? length_squared : 1.0);
  }
  for (std::size_t e = 0; e < n; ++e) {  // scatter
    const auto [i, j] = edges[e];
    const Vec3 f(s[e] * dx[e], s[e] * dy[e], s[e] * dz[e]);
    force[i] += f;
    force[j] -= f;
  }
}

// Σ_i (x_i − origin)·g_i in four partial sums (vertex i into sum i mod 4), added in a fixed order at the
// end: bit-identical every run, without one long chain of dependent additions.
double sum_of_dots_from(std::span<const Vec3> x, std::span<const Vec3> g, const Vec3& origin) {
  double sum0 = 0.0, sum1 = 0.0, sum2 = 0.0, sum3 = 0.0;
  std::size_t i = 0;
  for (; i + 4 <= x.size(); i += 4) {
    sum0 += (x[i] - origin).dot(g[i]);
    sum1 += (x[i + 1] - origin).dot(g[i + 1]);
    sum2 += (x[i + 2] - origin).dot(g[i + 2]);
    sum3 += (x[i + 3] - origin).dot(g[i + 3]);
  }
  for (; i < x.size(); ++i) sum0 += (x[i] - origin).dot(g[i]);
  return (sum0 + sum1) + (sum2 + sum3);
}

}  // namespace

void add_spring_dampers(const DistanceConstraints& constraints, std::span<const Vec3> x, std::span<const Vec3> v,
                        std::span<Vec3> force) {
  for (std::size_t first = 0; first < constraints.size(); first += kEdgeBlock) {
    const std::size_t n = std::min(kEdgeBlock, constraints.size() - first);
    const auto nonzero = [first, n](const std::vector<double>& values) {
      return std::any_of(values.begin() + static_cast<std::ptrdiff_t>(first),
                         values.begin() + static_cast<std::ptrdiff_t>(first + n), [](double a) { return a != 0.0; });
    };
    if (nonzero(constraints.damping_N_s_per_m)) {
      spring_damper_block<true>(constraints, first, n, x, v, force);
    } else if (nonzero(constraints.stiffness_N_per_m)) {
      spring_damper_block<false>(constraints, first, n, x, v, force);
    }
  }
}

double six_volume_of(std::span<const Triangle> faces, std::span<const Vec3> x, const Vec3& origin, std::size_t first,
                     std::size_t last, double six_volume) {
  for (std::size_t f = first; f < last; ++f) {
    const Vec3 a = x[faces[f][0]] - origin, b = x[faces[f][1]] - origin, c = x[faces[f][2]] - origin;
    six_volume += a.dot(b.cross(c));
  }
  return six_volume;
}

double enclosed_volume(std::span<const Triangle> faces, std::span<const Vec3> x) {
  return six_volume_of(faces, x, x[0], 0, faces.size()) / 6.0;
}

double volume_rate(std::span<const Triangle> faces, std::span<const Vec3> x, std::span<const Vec3> v) {
  const Vec3 origin = x[0];
  double six_rate = 0.0;
  for (const Triangle& f : faces) {
    const Vec3 a = x[f[0]] - origin, b = x[f[1]] - origin, c = x[f[2]] - origin;
    six_rate += v[f[0]].dot(b.cross(c)) + v[f[1]].dot(c.cross(a)) + v[f[2]].dot(a.cross(b));
  }
  return six_rate / 6.0;
}

void volume_gradient(std::span<const Triangle> faces, std::span<const Vec3> x, std::vector<Vec3>& gradient) {
  gradient.assign(x.size(), Vec3::Zero());
  for (const Triangle& f : faces) {
    const Vec3 area_vector = 0.5 * (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]);  // A n̂ [m²]
    for (int i : f) gradient[i] += area_vector / 3.0;
  }
}

double guarded_volume(double volume_m3, double rest_volume_m3) {
  constexpr double kMinimumVolumeFraction = 1e-3;  // of V0: the gas then pushes 1000× its rest pressure
  return std::max(volume_m3, kMinimumVolumeFraction * rest_volume_m3);
}

double volume_and_area_sums(std::span<const Triangle> faces, std::span<const Vec3> x, std::vector<Vec3>& area_sums) {
  // Pass over the faces: twice the area vector of each face, 2A_f·n̂ = (x_b − x_a)×(x_c − x_a), summed at
  // its three corners: g_i = Σ_{f ∋ i} 2A_f·n̂.
  area_sums.assign(x.size(), Vec3::Zero());
  for (const auto& [a, b, c] : faces) {
    const Vec3 xa = x[a];
    const Vec3 twice_area = (x[b] - xa).cross(x[c] - xa);
    area_sums[a] += twice_area;
    area_sums[b] += twice_area;
    area_sums[c] += twice_area;
  }
  // The volume from the same sums: x_a·(2A_f·n̂) = x_a·(x_b × x_c) is the same for each corner of f, so
  // 6V = Σ_f x_a·(2A_f·n̂) = ⅓ Σ_f (x_a + x_b + x_c)·(2A_f·n̂) = ⅓ Σ_i x_i·g_i, and Σ_i g_i = 0 on a closed
  // mesh lets x_i be taken relative to the first vertex (small round-off).
  return x.empty() ? 0.0 : sum_of_dots_from(x, area_sums, x[0]) / 18.0;
}

double gas_force_per_area_sum(double nRT_J, double volume_m3, double rest_volume_m3) {
  return nRT_J / guarded_volume(volume_m3, rest_volume_m3) / 6.0;  // P = nRT/V [Pa], a sixth of 2A·n̂ per corner
}

}  // namespace sim
