// The mesh stage's entry point: a body's mesh spec becomes a welded, validated, closed TriMesh.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/after_phase.hpp"
#include "mesh/check.hpp"
#include "mesh/mesh_limits.hpp"
#include "mesh/repair_options.hpp"
#include "mesh/repair_step.hpp"
#include "mesh/trimesh.hpp"

namespace mesh {

struct LoadedMesh {
  TriMesh mesh;
  std::vector<std::string> notes;  // fixes applied (e.g. flipped winding), for the user
};

// `spec` is a generator ("icosphere:3") or, with `file` set, the spec as written in the scene.
// Throws softbody::InputError whose message starts with `context` (e.g. "scene.json: bodies.0.mesh"); a
// defect that repair fixes ends with the option that fixes it. A file is read within `limits`
// (mesh/import.hpp), welded, and repaired by `repair.step` (geometry::repair_mesh, which the caller passes in) when
// `repair.options.enabled`, before validation.
// `after_phase` is called after each of reading (and welding), repairing, and checking the mesh.
LoadedMesh load_closed_mesh(const std::string& spec, const std::filesystem::path& file, const std::string& context,
                            const MeshLimits& limits = {}, const Repair& repair = {},
                            const softbody::AfterPhase& after_phase = {});

// The words appended to a validation error of a file: which repair fixes `defect` ("" where none does).
// With `repair.enabled` the mesh was repaired already: the words say which step was off, or that repair was not
// enough and what it did (`repair_notes`: its notes, which are printed only for a mesh that loads).
std::string repair_hint(MeshDefect defect, const RepairOptions& repair, const std::filesystem::path& file,
                        const std::vector<std::string>& repair_notes = {});

}  // namespace mesh
