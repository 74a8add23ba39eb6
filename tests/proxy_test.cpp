// A body simulated on a remeshed proxy ("resolution") with its detailed mesh carried along: the binding
// reproduces the detailed mesh on the rest proxy, follows rigid motions exactly and uniform scales closely,
// and render and export show the detailed mesh while the simulation runs on the proxy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include <Eigen/Geometry>

#include "core/errors.hpp"
#include "mesh/generators.hpp"
#include "mesh/load.hpp"
#include "output/mesh_exporter.hpp"
#include "output/point_cache.hpp"
#include "output/shown_surface.hpp"
#include "scene/scene_json.hpp"
#include "setup/bind_skin.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

// A bumpy sphere (icosphere:4, 2562 vertices, radius 1 ± 5 %): a detailed surface that is not the proxy's.
mesh::TriMesh bumpy_sphere() {
  mesh::TriMesh m = mesh::icosphere(4);
  for (Vec3& x : m.vertices)
    x *= 1.0 + 0.05 * std::sin(5.0 * x.x()) * std::cos(4.0 * x.y()) * std::sin(3.0 * x.z() + 1.0);
  return m;
}

struct Bound {
  mesh::TriMesh detailed = bumpy_sphere();
  mesh::TriMesh proxy = mesh::icosphere(2);  // 162 vertices
  sim::Skin skin = setup::bind_skin(detailed.vertices, detailed.triangles, proxy.vertices, proxy.triangles, 0);

  std::vector<Vec3> on(const std::vector<Vec3>& proxy_x) const {
    std::vector<Vec3> normals, detailed_x;
    sim::skin_positions(skin, proxy_x, proxy.triangles, normals, detailed_x);
    return detailed_x;
  }
};

double largest_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, (a[i] - b[i]).norm());
  return largest;
}

TEST(SkinBinding, ReproducesTheDetailedMeshOnTheRestProxy) {
  const Bound bound;
  ASSERT_EQ(bound.skin.vertex_count(), bound.detailed.vertices.size());
  int smooth = 0;
  for (const sim::SkinAnchor& a : bound.skin.anchors) smooth += a.face_normal ? 0 : 1;
  std::printf("anchors along interpolated normals: %d of %zu\n", smooth, bound.skin.vertex_count());
  // Nearly every vertex solves the smooth (interpolated-normal) form; the face-normal form is the fallback.
  EXPECT_GT(smooth, static_cast<int>(0.95 * static_cast<double>(bound.skin.vertex_count())));
  // Round-off only: a body of radius 1 [m], so 1e-12 m is thousands of ulps of slack.
  EXPECT_LT(largest_distance(bound.on(bound.proxy.vertices), bound.detailed.vertices), 1e-12);
}

TEST(SkinBinding, FollowsARigidMotionExactly) {
  const Bound bound;
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 translation(0.3, -1.2, 2.5);
  const auto moved = [&](const std::vector<Vec3>& x) {
    std::vector<Vec3> y;
    for (const Vec3& p : x) y.push_back(rotation * p + translation);
    return y;
  };
  // The proxy's unit normals rotate with it, so every anchor gives R q + t: exact up to round-off.
  EXPECT_LT(largest_distance(bound.on(moved(bound.proxy.vertices)), moved(bound.detailed.vertices)), 1e-12);
}

TEST(SkinBinding, StaysCloseUnderAUniformScale) {
  const Bound bound;
  const double s = 1.1;
  std::vector<Vec3> proxy_x;
  for (const Vec3& p : bound.proxy.vertices) proxy_x.push_back(s * p);
  const std::vector<Vec3> detailed_x = bound.on(proxy_x);
  std::vector<Vec3> normals;
  sim::vertex_normals(bound.proxy.vertices, bound.proxy.triangles, normals);  // unchanged by the scale
  // The foot point scales with the proxy, the offset d along the normal n does not (unit vertex normals do
  // not scale): each vertex lands exactly (s − 1)·|d|·|n| from s·q, |n| = 1 for a face normal and
  // |Σ b_i n_i| (about 1) for the interpolated one. A few millimetres here, not the 10 cm the scale moves it.
  double largest = 0.0;
  for (std::size_t i = 0; i < detailed_x.size(); ++i) {
    const sim::SkinAnchor& a = bound.skin.anchors[i];
    const softbody::Triangle& t = bound.proxy.triangles[static_cast<std::size_t>(a.triangle)];
    const auto n_at = [&](int corner) {
      return normals[static_cast<std::size_t>(t[static_cast<std::size_t>(corner)])];
    };
    const double n_length =
        a.face_normal ? 1.0 : ((1.0 - a.b1 - a.b2) * n_at(0) + a.b1 * n_at(1) + a.b2 * n_at(2)).norm();
    const double error = (detailed_x[i] - s * bound.detailed.vertices[i]).norm();
    EXPECT_NEAR(error, (s - 1.0) * std::abs(a.offset_m) * n_length, 1e-12) << "vertex " << i;
    largest = std::max(largest, error);
  }
  std::printf("uniform scale 1.1: largest distance from the scaled mesh %.3g m (radius 1 m)\n", largest);
  EXPECT_LT(largest, 0.01);
}

// Two unit spheres whose centres are `gap` apart along x, as one mesh of two parts (the second part's vertices
// after the first's), each an icosphere:L: how a teapot's spout passes into its body.
mesh::TriMesh two_crossing_spheres(int levels, double gap) {
  mesh::TriMesh m = mesh::icosphere(levels);
  const mesh::TriMesh second = mesh::icosphere(levels);
  const int offset = static_cast<int>(m.vertices.size());
  for (const Vec3& x : second.vertices) m.vertices.push_back(x + Vec3(gap, 0, 0));
  for (const softbody::Triangle& t : second.triangles)
    m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return m;
}

TEST(SkinBinding, EachPartFollowsItsOwnProxyPart) {
  // The second sphere's vertices inside the first (x from 0.2 to 1) lie nearer to the first sphere's surface
  // than to their own; anchored there they would stay behind when the parts separate.
  const mesh::TriMesh detailed = two_crossing_spheres(3, 1.2);  // 2 × 642 vertices
  const mesh::TriMesh proxy = two_crossing_spheres(2, 1.2);     // 2 × 162 vertices
  const sim::Skin skin = setup::bind_skin(detailed.vertices, detailed.triangles, proxy.vertices, proxy.triangles, 0);
  const std::size_t half_proxy = proxy.vertices.size() / 2, half_detailed = detailed.vertices.size() / 2;
  std::vector<Vec3> proxy_x = proxy.vertices;
  const Vec3 apart(5.0, 0.0, 0.0);  // m: the second part moved away rigidly
  for (std::size_t i = half_proxy; i < proxy_x.size(); ++i) proxy_x[i] += apart;
  std::vector<Vec3> normals, detailed_x;
  sim::skin_positions(skin, proxy_x, proxy.triangles, normals, detailed_x);
  double largest = 0.0;  // each detailed vertex moves exactly as its own part: a translation, round-off only
  for (std::size_t i = 0; i < detailed_x.size(); ++i) {
    const Vec3 expected = detailed.vertices[i] + (i < half_detailed ? Vec3::Zero() : apart);
    largest = std::max(largest, (detailed_x[i] - expected).norm());
  }
  EXPECT_LT(largest, 1e-12);
}

// --- the scene key --------------------------------------------------------------------------------------------

std::string error_of(const std::string& body_json) {
  try {
    testing_support::scene_from_text(R"({ "bodies": [ )" + body_json + " ] }");
  } catch (const softbody::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ProxyScene, ReadsBothFormsAndRefusesOthers) {
  const scene::Scene count = testing_support::scene_from_text(R"({ "bodies": [ { "resolution": 2000 } ] })");
  EXPECT_EQ(count.bodies[0].resolution_vertices, 2000);
  const scene::Scene length =
      testing_support::scene_from_text(R"({ "bodies": [ { "resolution": { "edge_length": 0.05 } } ] })");
  EXPECT_EQ(length.bodies[0].resolution_edge_length_m, 0.05);
  EXPECT_EQ(testing_support::scene_from_text(R"({ "bodies": [ {} ] })").bodies[0].resolution_vertices, 0);

  EXPECT_NE(
      error_of(R"({ "resolution": 5 })").find("bodies.0.resolution: expected an integer in 20..1000000, got number 5"),
      std::string::npos)
      << error_of(R"({ "resolution": 5 })");
  EXPECT_NE(error_of(R"({ "resolution": { "edge_length": -1 } })")
                .find("bodies.0.resolution.edge_length: expected a finite number > 0"),
            std::string::npos);
  EXPECT_NE(error_of(R"({ "resolution": { "edges": 1 } })").find("bodies.0.resolution: expected {\"edge_length\": L}"),
            std::string::npos)
      << error_of(R"({ "resolution": { "edges": 1 } })");
}

TEST(ProxyScene, AnEdgeLengthFarTooShortIsBadInput) {
  // Unit sphere, area 4π: L = 1e-4 m would make about 2·4π / (√3·1e-8) ≈ 1.5e9 vertices.
  try {
    testing_support::world_from_text(
        R"({ "bodies": [ { "mesh": "icosphere:1", "resolution": { "edge_length": 1e-4 } } ] })");
    ADD_FAILURE() << "no error";
  } catch (const softbody::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "bodies.0.resolution.edge_length: expected an edge length giving at most 1000000 vertices"),
              std::string::npos)
        << e.what();
  }
}

constexpr const char* kProxyAndPlain = R"({
  "bodies": [ { "mesh": "icosphere:4", "resolution": 300, "position": [0, 2, 0] },
              { "mesh": "icosphere:2", "position": [3, 2, 0] } ] })";

TEST(ProxyScene, SimulatesOnTheProxyAndCarriesTheMesh) {
  const sim::World world = testing_support::world_from_text(kProxyAndPlain);
  ASSERT_EQ(world.model.bodies.size(), 2u);
  EXPECT_NEAR(world.model.bodies[0].vertex_count, 300, 30);
  EXPECT_EQ(world.model.bodies[1].vertex_count, 162);
  ASSERT_EQ(world.model.skins.size(), 1u);
  EXPECT_EQ(world.model.skin_of(1), nullptr);
  const sim::Skin* skin = world.model.skin_of(0);
  ASSERT_NE(skin, nullptr);
  EXPECT_EQ(skin->vertex_count(), 2562u);
  EXPECT_EQ(skin->triangles.size(), 5120u);
  // At t = 0 the shown surface is the placed icosphere:4, to round-off.
  output::ShownPositions shown;
  const std::span<const Vec3> x = shown.of(world, 0);
  const mesh::TriMesh sphere = mesh::icosphere(4);
  double largest = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    largest = std::max(largest, (x[i] - (sphere.vertices[i] + Vec3(0, 2, 0))).norm());
  EXPECT_LT(largest, 1e-12);
}

TEST(ProxyScene, ExportedFramesHoldTheDetailedMesh) {
  sim::World world = testing_support::world_from_text(kProxyAndPlain);
  testing_support::run_steps(world, 200, 1e-4);  // moving and deformed
  const std::size_t shown_vertices = 2562 + 162;
  for (const output::MeshFormat format : {output::MeshFormat::Obj, output::MeshFormat::Ply}) {
    const std::filesystem::path dir =
        testing_support::scratch_dir(format == output::MeshFormat::Obj ? "proxy_obj" : "proxy_ply");
    output::MeshExporter exporter(dir, format);
    exporter.on_frame(3, world.state.time_s, world);
    const mesh::LoadedMesh loaded =
        mesh::load_closed_mesh(exporter.frame_path(3).string(), exporter.frame_path(3), "export");
    EXPECT_EQ(loaded.mesh.vertices.size(), shown_vertices);
    EXPECT_EQ(loaded.mesh.triangles.size(), 5120u + 320u);
  }
  const std::filesystem::path dir = testing_support::scratch_dir("proxy_pc2");
  output::PointCacheExporter cache(dir, output::PointCacheFormat::Pc2);
  cache.on_frame(0, world.state.time_s, world);
  cache.finish(true);
  std::ifstream pc2(cache.cache_path(0), std::ios::binary);
  char header[32];
  pc2.read(header, sizeof header);
  std::int32_t points = 0;
  std::memcpy(&points, header + 16, 4);  // after the 12-byte signature and the int32 version
  EXPECT_EQ(points, 2562);
  const mesh::LoadedMesh obj = mesh::load_closed_mesh(cache.mesh_path(0).string(), cache.mesh_path(0), "pc2 mesh");
  EXPECT_EQ(obj.mesh.vertices.size(), 2562u);
}

TEST(ProxyScene, RendersAndExportsEndToEnd) {
  const std::filesystem::path dir = testing_support::scratch_dir("proxy_render");
  const auto render =
      testing_support::run_softbody("render tests/scenes/proxy_render.json -o " + (dir / "frames").string());
  ASSERT_EQ(render.exit_status, 0) << render.output;
  EXPECT_NE(render.output.find("bodies.0.resolution: simulated on an isotropic remesh of"), std::string::npos)
      << render.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "frame_0000.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "frame_0002.png"));
  const auto csv =
      testing_support::run_softbody("simulate tests/scenes/proxy_render.json --csv " + (dir / "run.csv").string());
  ASSERT_EQ(csv.exit_status, 0) << csv.output;
  const auto exported =
      testing_support::run_softbody("export tests/scenes/proxy_render.json --format obj -o " + (dir / "obj").string());
  ASSERT_EQ(exported.exit_status, 0) << exported.output;
  const std::filesystem::path last = dir / "obj" / "frame_0002.obj";
  const mesh::LoadedMesh loaded = mesh::load_closed_mesh(last.string(), last, "export");
  EXPECT_EQ(loaded.mesh.vertices.size(), 2562u);
}

}  // namespace
