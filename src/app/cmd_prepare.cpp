// `softbody prepare IN OUT [--resolution N] [--parts union|keep|largest]`: a mesh file read, welded, repaired and
// validated as a body's mesh would be, and written to OUT (OBJ, PLY or STL) so that it can be inspected.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.hpp"
#include "core/errors.hpp"
#include "frames/stop_request.hpp"
#include "geometry/mesh_repair.hpp"
#include "geometry/remesh.hpp"
#include "geometry/uv_transfer.hpp"
#include "mesh/check.hpp"
#include "mesh/load.hpp"
#include "mesh/parts.hpp"
#include "output/mesh_file_writer.hpp"

namespace app {
namespace {

struct PrepareOptions {
  std::string input;
  std::string output;
  std::optional<int> resolution;
  mesh::PartsPolicy parts = mesh::PartsPolicy::Union;
};

// The prepared mesh in one line: size, enclosed volume and the properties validation established.
void print_summary(const std::string& output, const mesh::TriMesh& prepared, double wall_s) {
  const mesh::EdgeCounts edges = mesh::count_edges(prepared);
  const int parts = mesh::edge_connected_parts(prepared).count;
  std::printf(
      "prepared %s: %zu vertices, %zu triangles, %zu edges, %d part%s; volume %.6g (mesh units^3); closed "
      "(%zu boundary edges), manifold (%zu edges with three or more faces), wound outward; in %.3f s\n",
      output.c_str(), prepared.vertices.size(), prepared.triangles.size(), edges.edges, parts, parts == 1 ? "" : "s",
      mesh::signed_volume(prepared), edges.boundary, edges.non_manifold, wall_s);
}

int run_prepare(const PrepareOptions& options) {
  // SIGINT / SIGTERM end it when the phase in progress (reading, repairing, checking, remeshing) ends, before
  // OUT is written; the write itself, once started, finishes.
  frames::stop_on_signals();
  const auto start = std::chrono::steady_clock::now();
  if (options.resolution && (*options.resolution < 20 || *options.resolution > 1000000)) {
    throw softbody::InputError("--resolution " + std::to_string(*options.resolution) +
                               ": expected a vertex count from 20 to 1000000 (the remeshed surface's)");
  }
  if (!output::mesh_file_format_of(options.output)) {
    throw softbody::InputError(options.output + ": expected an output file name ending in .obj, .ply or .stl");
  }
  mesh::RepairOptions repair = mesh::full_repair();
  repair.parts = options.parts;
  const mesh::LoadedMesh prepared =
      mesh::load_closed_mesh(options.input, options.input, "prepare", {}, {repair, geometry::repair_mesh},
                             frames::throw_if_stop_requested_after);
  for (const std::string& note : prepared.notes) std::cerr << "note: " << note << "\n";
  mesh::TriMesh result = prepared.mesh;
  if (options.resolution) {
    result = geometry::remesh_to_vertex_count(prepared.mesh, *options.resolution);
    result.corner_uvs = geometry::transfer_corner_uvs(prepared.mesh, result);  // none where the file had none
    frames::throw_if_stop_requested_after("remeshing " + options.input + " to about " +
                                          std::to_string(*options.resolution) + " vertices");
    std::cerr << "note: remeshed isotropically from " << prepared.mesh.vertices.size() << " to "
              << result.vertices.size() << " vertices (--resolution " << *options.resolution << ")\n";
  }
  output::write_mesh_file(options.output, result, "prepared by softbody prepare from " + options.input);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_summary(options.output, result, wall_s);
  return 0;
}

}  // namespace

Action register_prepare(CLI::App& parent) {
  auto options = std::make_shared<PrepareOptions>();
  CLI::App* command = parent.add_subcommand(
      "prepare", "Repair, weld and validate a mesh file as a body with \"repair\": true would, and write the result");
  command->add_option("IN", options->input, "The mesh file to prepare (OBJ, PLY, STL, glTF, ... as a scene's mesh)")
      ->required();
  command
      ->add_option("OUT", options->output,
                   "Where to write the prepared mesh: .obj, .ply or .stl (written whole or not at all)")
      ->required();
  command
      ->add_option("--resolution", options->resolution,
                   "Also remesh isotropically to about N vertices (CGAL; what a body's \"resolution\": N simulates on)")
      ->type_name("N")
      ->check(CLI::Range(4, 10'000'000));
  command
      ->add_option(
          "--parts", options->parts,
          "Separate parts: union (default: the ones that overlap, touch or nest joined into one surface), keep every "
          "one as it is, or only the largest (most faces)")
      ->transform(
          CLI::CheckedTransformer(std::map<std::string, mesh::PartsPolicy>{{"union", mesh::PartsPolicy::Union},
                                                                           {"keep", mesh::PartsPolicy::Keep},
                                                                           {"largest", mesh::PartsPolicy::Largest}}));
  return [options] { return run_prepare(*options); };
}

}  // namespace app
