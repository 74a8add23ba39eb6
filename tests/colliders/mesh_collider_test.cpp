// Mesh colliders: the signed distance of a closed mesh against the analytic shape it approximates (a cube mesh is a
// box to round-off; an icosphere a sphere within its facets' sagitta), its inside test against the winding number,
// the tree's nearest point against a search of every triangle, an open quad as a sheet of its thickness; a body
// dropped on a cube mesh moves as on the box collider, and a quad sheet stops a falling body; files that are not
// meshes give a clear error (exit 2); export writes the colliders and they read back.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/euler_rotation.hpp"
#include "mesh/generators.hpp"
#include "mesh/import.hpp"
#include "sim/contact/collider_mesh.hpp"
#include "sim/contact/collider_shape.hpp"
#include "sim/step/diagnostics.hpp"
#include "test_helpers.hpp"

namespace {

using sim::ColliderGeometry;
using sim::ColliderShape;
using softbody::Vec3;

// A collider at a pose off the origin, turned about all three axes.
ColliderGeometry posed(ColliderShape shape) {
  ColliderGeometry g;
  g.shape = shape;
  g.position_m = Vec3(0.1, 0.2, -0.3);
  g.rotation = softbody::rotation_xyz_degrees(Vec3(10, 20, 30));
  return g;
}

// The posed collider of mesh `m` scaled by `scale` (thickness: an open mesh's).
ColliderGeometry posed_mesh(const mesh::TriMesh& m, double scale, double thickness_m = 0.01) {
  ColliderGeometry g = posed(ColliderShape::Mesh);
  std::vector<Vec3> vertices;
  for (const Vec3& p : m.vertices) vertices.push_back(scale * p);
  g.mesh = sim::make_collider_mesh(vertices, m.triangles, thickness_m);
  g.world_reach_m = sim::world_reach(g);
  return g;
}

// Random points in a box of half side `reach` about the collider's position.
std::vector<Vec3> random_points(const ColliderGeometry& g, double reach, int count) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> coordinate(-reach, reach);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    points.push_back(g.position_m + Vec3(coordinate(random), coordinate(random), coordinate(random)));
  }
  return points;
}

// The winding number of a closed mesh about world point x: Σ of its triangles' signed solid angles / 4π (Van
// Oosterom & Strackee 1983: tan(Ω/2) = a·(b × c) / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|)). 1 inside, 0 outside.
double winding_number(const ColliderGeometry& g, const Vec3& x) {
  const sim::ColliderMesh& m = *g.mesh;
  const Vec3 q = g.rotation.transpose() * (x - g.position_m);
  double solid_angle = 0.0;
  for (const softbody::Triangle& t : m.triangles) {
    const Vec3 a = m.vertices_m[static_cast<std::size_t>(t[0])] - q,
               b = m.vertices_m[static_cast<std::size_t>(t[1])] - q,
               c = m.vertices_m[static_cast<std::size_t>(t[2])] - q;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    solid_angle += 2.0 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
  }
  return solid_angle / (4.0 * std::numbers::pi);
}

TEST(MeshCollider, ClosedCubeMeshIsTheBoxToRoundOff) {
  ColliderGeometry box = posed(ColliderShape::Box);
  box.half_size_m = Vec3::Constant(0.4);
  box.world_reach_m = sim::world_reach(box);
  const ColliderGeometry cube = posed_mesh(mesh::cube(3), 0.8);
  ASSERT_TRUE(cube.mesh->closed);
  int inside = 0;
  for (const Vec3& x : random_points(box, 0.9, 20000)) {
    const sim::SurfacePoint expected = sim::nearest_surface(box, x), actual = sim::nearest_surface(cube, x);
    ASSERT_NEAR(actual.distance_m, expected.distance_m, 1e-12) << x.transpose();
    EXPECT_LT((actual.closest_m - expected.closest_m).norm(), 1e-9) << x.transpose();
    ASSERT_EQ(sim::is_inside(cube, x), sim::is_inside(box, x)) << x.transpose();
    inside += sim::is_inside(cube, x) ? 1 : 0;
  }
  EXPECT_GT(inside, 1000);  // the points test both sides
}

TEST(MeshCollider, IcosphereMeshIsTheSphereWithinItsSagitta) {
  ColliderGeometry sphere = posed(ColliderShape::Sphere);
  sphere.radius_m = 0.5;
  const ColliderGeometry ico = posed_mesh(mesh::icosphere(4), 0.5);
  // Every point of the mesh lies between the sphere and the nearest of its faces' planes (its corners are on the
  // sphere), so the two distances differ by at most the sagitta r − min over faces of the plane's distance n·a.
  double nearest_plane = sphere.radius_m;
  for (std::size_t t = 0; t < ico.mesh->triangles.size(); ++t) {
    const Vec3& corner = ico.mesh->vertices_m[static_cast<std::size_t>(ico.mesh->triangles[t][0])];
    nearest_plane = std::min(nearest_plane, ico.mesh->face_normals[t].dot(corner));
  }
  const double sagitta = sphere.radius_m - nearest_plane + 1e-12;
  ASSERT_LT(sagitta, 0.002 * sphere.radius_m);
  double largest = 0.0;
  for (const Vec3& x : random_points(sphere, 1.0, 20000)) {
    const double expected = sim::nearest_surface(sphere, x).distance_m;
    const double actual = sim::nearest_surface(ico, x).distance_m;
    largest = std::max(largest, std::abs(actual - expected));
    ASSERT_NEAR(actual, expected, sagitta) << x.transpose();
    if (std::abs(expected) > sagitta) {
      ASSERT_EQ(sim::is_inside(ico, x), expected < 0.0) << x.transpose();
    }
  }
  std::printf("icosphere:4 against the sphere: largest distance difference %.3g r (sagitta %.3g r)\n",
              largest / sphere.radius_m, sagitta / sphere.radius_m);
}

// The pseudo-normals' side is the winding number's wherever the winding number is clearly 0 or 1, also for the mesh
// wound inside out (turned at load) and for points near the surface, edges and corners.
TEST(MeshCollider, InsideAgreesWithTheWindingNumber) {
  mesh::TriMesh turned = mesh::icosphere(2);
  for (softbody::Triangle& t : turned.triangles) std::swap(t[1], t[2]);
  for (const mesh::TriMesh& m : {mesh::icosphere(2), turned, mesh::cube(2)}) {
    const ColliderGeometry g = posed_mesh(m, 0.5);
    ASSERT_TRUE(g.mesh->closed);
    for (const Vec3& x : random_points(g, 0.6, 5000)) {
      const double w = winding_number(g, x);
      ASSERT_TRUE(std::abs(w) < 1e-9 || std::abs(w - 1.0) < 1e-9) << w;  // closed: never in between
      ASSERT_EQ(sim::is_inside(g, x), w > 0.5) << x.transpose();
      EXPECT_EQ(sim::nearest_surface(g, x).distance_m<0.0, w> 0.5) << x.transpose();
    }
  }
}

TEST(MeshCollider, TreeFindsTheNearestOfAllTriangles) {
  const ColliderGeometry g = posed_mesh(mesh::icosphere(3), 0.5);
  const sim::ColliderMesh& m = *g.mesh;
  for (const Vec3& x : random_points(g, 1.5, 2000)) {
    const Vec3 q = g.rotation.transpose() * (x - g.position_m);
    double nearest = std::numeric_limits<double>::infinity();
    for (const softbody::Triangle& t : m.triangles) {  // each triangle's nearest point, by a one-triangle mesh
      const std::vector<Vec3> corners{m.vertices_m[static_cast<std::size_t>(t[0])],
                                      m.vertices_m[static_cast<std::size_t>(t[1])],
                                      m.vertices_m[static_cast<std::size_t>(t[2])]};
      const auto triangle = sim::make_collider_mesh(corners, {{0, 1, 2}}, 0.0);
      nearest = std::min(nearest, sim::mesh_nearest_local(*triangle, q).distance_m);
    }
    ASSERT_NEAR(std::abs(sim::nearest_surface(g, x).distance_m), nearest, 1e-12) << x.transpose();
  }
}

TEST(MeshCollider, OpenQuadIsASheetOfItsThickness) {
  mesh::TriMesh quad;
  quad.vertices = {Vec3(-1, 0, -1), Vec3(-1, 0, 1), Vec3(1, 0, 1), Vec3(1, 0, -1)};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  ColliderGeometry g;
  g.shape = ColliderShape::Mesh;
  g.mesh = sim::make_collider_mesh(quad.vertices, quad.triangles, 0.02);
  g.world_reach_m = sim::world_reach(g);
  ASSERT_FALSE(g.mesh->closed);
  EXPECT_EQ(g.mesh->boundary_edges, 4u);
  // Over the quad, either side: |y| − t/2, the normal away from it, the closest point on the sheet's face.
  for (const double y : {0.3, 0.005, -0.005, -0.3}) {
    const sim::SurfacePoint s = sim::nearest_surface(g, Vec3(0.2, y, 0.4));
    EXPECT_NEAR(s.distance_m, std::abs(y) - 0.01, 1e-15) << y;
    EXPECT_LT((s.normal - Vec3(0, y > 0 ? 1 : -1, 0)).norm(), 1e-12) << y;
    EXPECT_NEAR((s.closest_m - Vec3(0.2, y > 0 ? 0.01 : -0.01, 0.4)).norm(), 0.0, 1e-15) << y;
    EXPECT_EQ(sim::is_inside(g, Vec3(0.2, y, 0.4)), std::abs(y) < 0.01) << y;
  }
  // Beyond an edge: the distance to the edge less t/2 (a rounded rim).
  EXPECT_NEAR(sim::nearest_surface(g, Vec3(1.3, 0.4, 0)).distance_m, 0.5 - 0.01, 1e-15);
  EXPECT_TRUE(sim::is_inside(g, Vec3(1.005, 0.0, 0.5)));  // within the rim's half thickness
  EXPECT_FALSE(sim::is_inside(g, Vec3(1.02, 0.0, 0.5)));
  // The quad with both windings (every edge used twice, opposite ways) encloses no volume: a sheet too.
  std::vector<softbody::Triangle> both = quad.triangles;
  for (const softbody::Triangle& t : quad.triangles) both.push_back({t[0], t[2], t[1]});
  const auto layers = sim::make_collider_mesh(quad.vertices, both, 0.02);
  EXPECT_FALSE(layers->closed);
  EXPECT_TRUE(sim::mesh_inside_local(*layers, Vec3(0.2, 0.005, 0.4)));
}

// A soft ball dropped on the corner region of a turned box, and on the same box as a cube mesh: the same motion, in
// every contact model (the distances agree to round-off; chaos in 1 s of bouncing amplifies that to far below 1 mm).
TEST(MeshCollider, BallOnACubeMeshMovesAsOnTheBox) {
  for (const char* contact : {"paper", "friction", "smooth"}) {
    const auto ball_on = [&](const std::string& shape) {
      return R"({ "duration": 1.0, "solver": { "integrator": "xpbd", "dt": "auto" },
                  "floor": { "height": -2, "contact": ")" +
             std::string(contact) + R"(", "restitution": 0.2, "friction": 0.5 },
                  "colliders": [ )" +
             shape + R"( ],
                  "bodies": [ { "mesh": "icosphere:2", "scale": 0.2, "position": [0.1, 0.6, 0], "stiffness": 800,
                                "damping": {"ratio": 0.5}, "pressure": {"inflation": 0.05} } ] })";
    };
    sim::World on_box = testing_support::world_from_text(
        ball_on(R"({"shape": "box", "size": [0.5, 0.5, 0.5], "position": [0, 0, 0], "rotation": [0, 0, 10]})"));
    sim::World on_mesh = testing_support::world_from_text(
        ball_on(R"({"shape": "mesh", "mesh": "cube:1", "scale": 0.5, "position": [0, 0, 0], "rotation": [0, 0, 10]})"));
    const double dt = on_box.model.solver.dt_s;
    ASSERT_EQ(dt, on_mesh.model.solver.dt_s);
    const auto steps = static_cast<long long>(std::round(1.0 / dt));
    double deepest = 0.0;
    for (long long s = 0; s < steps; ++s) {
      on_box.step(dt);
      on_mesh.step(dt);
      for (const Vec3& x : on_mesh.state.x) {
        deepest = std::max(deepest, -sim::nearest_surface(on_box.model.colliders[0].geometry, x).distance_m);
      }
    }
    const Vec3 box_centre = sim::diagnose(on_box.model, on_box.state, 0).com_m;
    const Vec3 mesh_centre = sim::diagnose(on_mesh.model, on_mesh.state, 0).com_m;
    std::printf("%s: centre on the mesh %.6f m high, on the box %.6f m (difference %.3g m), deepest %.3g m\n", contact,
                mesh_centre.y(), box_centre.y(), (mesh_centre - box_centre).norm(), deepest);
    EXPECT_LT((mesh_centre - box_centre).norm(), 1e-4) << contact;
    EXPECT_LT(deepest, std::string(contact) == "smooth" ? 0.01 : 1e-12) << contact;  // smooth: v τ + δ ≈ 9 mm
  }
}

// A ball dropped from 0.5 m onto a 2 m square (tests/data/quad.obj, no volume, 1 cm thick) stays on top of it.
TEST(MeshCollider, OpenQuadStopsAFallingBody) {
  for (const char* contact : {"paper", "friction", "smooth"}) {
    sim::World world = testing_support::world_from_text(
        R"({ "solver": { "integrator": "xpbd", "dt": "auto" }, "colliders": [
              { "shape": "mesh", "mesh": "data/quad.obj", "position": [0, 1, 0], "contact": ")" +
        std::string(contact) + R"(", "restitution": 0.0 } ],
            "bodies": [ { "mesh": "icosphere:2", "scale": 0.2, "position": [0, 1.7, 0], "stiffness": 800,
                          "damping": {"ratio": 0.5}, "pressure": {"inflation": 0.05} } ] })");
    ASSERT_FALSE(world.model.colliders[0].geometry.mesh->closed);
    const double dt = world.model.solver.dt_s;
    double lowest = 10.0;  // the lowest any vertex came at any step [m]
    for (long long step = 0; step < static_cast<long long>(std::round(1.5 / dt)); ++step) {
      world.step(dt);
      for (const Vec3& x : world.state.x) lowest = std::min(lowest, x.y());
    }
    const double centre = sim::diagnose(world.model, world.state, 0).com_m.y();
    std::printf("%s: lowest vertex %.4f m (the sheet's top at 1.005 m), centre at the end %.3f m\n", contact, lowest,
                centre);
    // Never through the sheet's middle (the impulse models: never inside it; smooth: within its skin of ~1 cm), and
    // at the end on it (not fallen to -∞: the centre within 0.3 m above a ball of radius 0.2).
    EXPECT_GT(lowest, std::string(contact) == "smooth" ? 1.0 : 1.005 - 1e-12) << contact;
    EXPECT_GT(centre, 1.0) << contact;
    EXPECT_LT(centre, 1.5) << contact;
  }
}

std::string mesh_collider_scene(const std::string& file) {
  return R"({ "duration": 0.1, "colliders": [ { "shape": "mesh", "mesh": ")" + file +
         R"(" } ], "bodies": [ { "mesh": "icosphere:1", "position": [0, 3, 0] } ] })";
}

TEST(MeshCollider, FileThatIsNotAMeshIsRefusedWithExit2) {
  const std::filesystem::path dir = testing_support::scratch_dir("mesh_collider_refused");
  for (const char* name : {"not_a_mesh.obj", "no_area.obj", "missing.obj"}) {
    const std::filesystem::path scene = dir / (std::string(name) + ".json");
    std::ofstream(scene) << mesh_collider_scene(testing_support::data_path(name));
    const testing_support::CommandResult result =
        testing_support::run_softbody("simulate " + scene.string() + " --csv -");
    EXPECT_EQ(result.exit_status, 2) << result.output;
    EXPECT_NE(result.output.find("colliders.0.mesh"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(name), std::string::npos) << result.output;
  }
}

TEST(MeshCollider, ExportWritesTheCollidersAndTheyReadBack) {
  const std::filesystem::path dir = testing_support::scratch_dir("mesh_collider_export");
  const std::filesystem::path scene = dir / "scene.json";
  std::ofstream(scene) << R"({ "duration": 0.1, "colliders": [
      { "shape": "mesh", "mesh": ")" +
                              testing_support::data_path("cube_quads.obj") +
                              R"(", "scale": 0.5, "position": [0, 0.5, 0] },
      { "shape": "sphere", "radius": 0.3, "position": [2, 0, 0] },
      { "shape": "plane" } ], "bodies": [ { "mesh": "icosphere:1", "position": [0, 3, 0] } ] })";
  for (const char* format : {"obj", "ply"}) {
    const std::filesystem::path out = dir / format;
    const testing_support::CommandResult result = testing_support::run_softbody(
        "export " + scene.string() + " -o " + out.string() + " --frames 0 --format " + format);
    ASSERT_EQ(result.exit_status, 0) << result.output;
    const std::string extension = std::string(".") + format;
    const mesh::TriMesh cube = mesh::import_mesh_file(out / ("collider_0" + extension));
    EXPECT_EQ(cube.triangles.size(), 12u);
    Vec3 lo = cube.vertices.front(), hi = lo;
    for (const Vec3& p : cube.vertices) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    EXPECT_EQ(lo, Vec3(-0.5, 0.0, -0.5)) << format;  // the file's side 2, scaled by 0.5, placed 0.5 m up
    EXPECT_EQ(hi, Vec3(0.5, 1.0, 0.5)) << format;
    EXPECT_GT(mesh::import_mesh_file(out / ("collider_1" + extension)).triangles.size(), 100u);
    EXPECT_EQ(mesh::import_mesh_file(out / ("collider_2" + extension)).triangles.size(), 2u);
  }
}

}  // namespace
