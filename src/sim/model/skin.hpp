// A detailed surface carried along by a body's simulated (proxy) surface, as MuJoCo's mjModel carries skins:
// each detailed vertex sits at a point of a proxy triangle plus an offset along the proxy's normal there.
// Only render and export read it; the step never does.
#pragma once

#include <span>
#include <vector>

#include "core/vec.hpp"

namespace sim {

using softbody::Triangle;
using softbody::Vec3;

// Where one detailed vertex sits on the proxy. With corners x0, x1, x2 of `triangle` and b0 = 1 − b1 − b2:
//   q = b0·x0 + b1·x1 + b2·x2 + offset_m · n
// n = b0·n0 + b1·n1 + b2·n2 from the proxy's unit vertex normals n_i (smooth: the detailed mesh bends with
// the proxy), or the triangle's unit normal where that form has no solution near the triangle (face_normal).
struct SkinAnchor {
  int triangle = 0;          // proxy face index, local to the body
  double b1 = 0.0;           // barycentric weight of the triangle's second corner
  double b2 = 0.0;           // barycentric weight of the third corner
  double offset_m = 0.0;     // along n [m]
  bool face_normal = false;  // n is the triangle's unit normal instead of the interpolated vertex normals
};

struct Skin {
  int body = 0;                     // the model's body whose surface carries this skin
  std::vector<Triangle> triangles;  // the detailed mesh's own triangles, counter-clockwise seen from outside
  std::vector<SkinAnchor> anchors;  // one per detailed vertex, in the detailed mesh's vertex order
  std::vector<softbody::CornerUvs> corner_uvs;  // per detailed triangle, the file's UVs; empty when it has none
  std::size_t vertex_count() const { return anchors.size(); }
};

// The file's texture coordinates of a body that shows its simulated surface (no skin): per face of the body.
struct SurfaceUvs {
  int body = 0;
  std::vector<softbody::CornerUvs> corner_uvs;
};

// Unit area-weighted vertex normals: n_i ∝ Σ over faces at i of (x_b − x_a) × (x_c − x_a) (twice the area
// vector); a vertex whose sum vanishes gets (0, 0, 0).
void vertex_normals(std::span<const Vec3> x, std::span<const Triangle> faces, std::vector<Vec3>& normals);

// The anchor of point `q` on proxy triangle `triangle` (surface x, faces, unit vertex normals `normals`):
// Newton's method on q = Σ b_i x_i + d Σ b_i n_i for (b1, b2, d) from the projection onto the triangle's
// plane; where it does not converge or lands far outside the triangle, the projection along the face normal
// (exact by construction). Either reproduces q to round-off on the same proxy.
SkinAnchor anchor_point(const Vec3& q, int triangle, std::span<const Vec3> x, std::span<const Triangle> faces,
                        std::span<const Vec3> normals);

// The detailed vertices of `skin` on the proxy surface at `x` (the body's vertices) with `faces`; `normals`
// is scratch for the proxy's vertex normals. `detailed` is resized to the skin's vertex count.
void skin_positions(const Skin& skin, std::span<const Vec3> x, std::span<const Triangle> faces,
                    std::vector<Vec3>& normals, std::vector<Vec3>& detailed);

}  // namespace sim
