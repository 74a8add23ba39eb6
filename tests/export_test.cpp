// Mesh export: every frame's mesh, readable again as the same closed surface.
#include <gtest/gtest.h>

#include "mesh/load.hpp"
#include "output/mesh_exporter.hpp"
#include "sim/diagnostics.hpp"
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
  const double volume = sim::diagnose(world.model, world.state, 0).volume_m3 + sim::diagnose(world.model, world.state, 1).volume_m3;
  // OBJ keeps 9 significant digits, PLY single precision floats.
  EXPECT_NEAR(mesh::signed_volume(loaded.mesh), volume, 1e-5 * volume);
  // The one note: two bodies in one file are two separate closed parts ("split": true would separate them).
  ASSERT_EQ(loaded.notes.size(), 1u) << ::testing::PrintToString(loaded.notes);
  EXPECT_NE(loaded.notes[0].find("holds 2 separate closed parts"), std::string::npos) << loaded.notes[0];
}

INSTANTIATE_TEST_SUITE_P(Formats, MeshExport, ::testing::Values(output::MeshFormat::Obj, output::MeshFormat::Ply),
                         [](const auto& param) { return param.param == output::MeshFormat::Obj ? "obj" : "ply"; });

}  // namespace
