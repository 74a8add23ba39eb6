// Mesh export: every frame's mesh, readable again as the same closed surface, with the mesh file's UVs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "mesh/generators.hpp"
#include "mesh/import.hpp"
#include "mesh/load.hpp"
#include "output/mesh_exporter.hpp"
#include "output/mesh_file_writer.hpp"
#include "sim/step/diagnostics.hpp"
#include "test_helpers.hpp"

namespace {

class MeshExport : public ::testing::TestWithParam<output::MeshFormat> {};

TEST_P(MeshExport, FramesReimportAsTheSameClosedSurface) {
  sim::World world = testing_support::world_from_text(R"({
    "bodies": [ { "mesh": "icosphere:2", "position": [0, 2, 0] },
                { "mesh": "torus:24,12", "position": [3, 2, 0] } ] })");
  testing_support::run_steps(world, 500, 1e-4);  // deformed by the gas and moving
  const std::filesystem::path dir =
      testing_support::scratch_dir(GetParam() == output::MeshFormat::Obj ? "export_obj" : "export_ply");
  output::MeshExporter exporter(dir, GetParam());
  exporter.on_frame(7, world.state.time_s, world);
  const std::filesystem::path file = exporter.frame_path(7);
  EXPECT_EQ(file.filename().string().substr(0, 11), "frame_0007.");

  // Both bodies in one file: as one mesh it is still closed (two closed components).
  const mesh::LoadedMesh loaded = mesh::load_closed_mesh(file.string(), file, "export");
  EXPECT_EQ(loaded.mesh.vertices.size(), world.state.x.size());
  const double volume =
      sim::diagnose(world.model, world.state, 0).volume_m3 + sim::diagnose(world.model, world.state, 1).volume_m3;
  // OBJ keeps 9 significant digits, PLY single precision floats.
  EXPECT_NEAR(mesh::signed_volume(loaded.mesh), volume, 1e-5 * volume);
  // The one note: two bodies in one file are two separate closed parts ("split": true would separate them).
  ASSERT_EQ(loaded.notes.size(), 1u) << ::testing::PrintToString(loaded.notes);
  EXPECT_NE(loaded.notes[0].find("holds 2 separate closed parts"), std::string::npos) << loaded.notes[0];
}

// A cube whose UVs are laid out per face (each face its own square: a seam on every edge), as 0.3 × the two
// coordinates along the face plus the face's offset: values that are not exact in float.
mesh::TriMesh cube_with_face_uvs() {
  mesh::TriMesh cube = mesh::cube(3);
  for (const mesh::Triangle& t : cube.triangles) {
    const mesh::Vec3 n =
        (cube.vertices[static_cast<std::size_t>(t[1])] - cube.vertices[static_cast<std::size_t>(t[0])])
            .cross(cube.vertices[static_cast<std::size_t>(t[2])] - cube.vertices[static_cast<std::size_t>(t[0])]);
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    const double offset = axis + (n[axis] > 0.0 ? 0.5 : 0.0);
    mesh::CornerUvs uvs{};
    for (std::size_t k = 0; k < 3; ++k) {
      const mesh::Vec3& x = cube.vertices[static_cast<std::size_t>(t[k])];
      uvs[k] = {0.3 * (x[(axis + 1) % 3] + 0.5) + offset, 0.3 * (x[(axis + 2) % 3] + 0.5)};
    }
    cube.corner_uvs.push_back(uvs);
  }
  return cube;
}

bool same_bits(const std::vector<mesh::CornerUvs>& a, const std::vector<mesh::CornerUvs>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(mesh::CornerUvs)) == 0;
}

// The file's UVs come out of `export` as they went in, bit for bit, after a drop that moved and deformed the
// body: on its own mesh and on a proxy (the UVs ride on the detailed mesh the skin carries).
TEST(MeshExportUvs, SurviveADropBitForBit) {
  const std::filesystem::path source = testing_support::scratch_dir("export_uvs") / "cube_uvs.obj";
  output::write_mesh_file(source, cube_with_face_uvs(), "a cube with per-face UVs");
  const mesh::TriMesh original = mesh::import_mesh_file(source);
  ASSERT_EQ(original.corner_uvs.size(), original.triangles.size());
  for (const char* resolution : {"null", "150"}) {
    sim::World world =
        testing_support::world_from_text(R"({ "bodies": [ { "mesh": ")" + source.string() +
                                         R"(", "position": [0, 0.8, 0], "resolution": )" + resolution + " } ] }");
    testing_support::run_steps(world, 4000, 1e-4);  // 0.4 s: fallen 0.3 m onto the floor and squashed
    const std::filesystem::path dir =
        testing_support::scratch_dir(std::string("export_uvs_") + (resolution[0] == 'n' ? "raw" : "proxy"));
    output::MeshExporter exporter(dir, output::MeshFormat::Obj);
    exporter.on_frame(1, world.state.time_s, world);
    const mesh::TriMesh exported = mesh::import_mesh_file(exporter.frame_path(1));
    ASSERT_EQ(exported.triangles.size(), original.triangles.size()) << resolution;
    EXPECT_TRUE(same_bits(exported.corner_uvs, original.corner_uvs)) << resolution;
    double lowest = 1e9;  // it fell: the bottom face (at y = 0.3 at the start) is near the floor now
    for (const mesh::Vec3& x : exported.vertices) lowest = std::min(lowest, x.y());
    EXPECT_LT(lowest, 0.05) << resolution;
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, MeshExport, ::testing::Values(output::MeshFormat::Obj, output::MeshFormat::Ply),
                         [](const auto& param) { return param.param == output::MeshFormat::Obj ? "obj" : "ply"; });

}  // namespace
