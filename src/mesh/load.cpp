// Generator or file → weld → repair (when asked) → validate: the closed surface a body is built from.
#include "mesh/load.hpp"

#include <cstdio>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/one_line.hpp"
#include "mesh/check.hpp"
#include "mesh/generators.hpp"
#include "mesh/import.hpp"
#include "mesh/parts.hpp"
#include "mesh/self_intersection.hpp"
#include "mesh/weld.hpp"

namespace mesh {
namespace {

// What joins overlapping parts into one surface, for a note on a mesh whose parts pass into each other: the
// union repair where it was not asked for ("" where it ran: its own note says why it could not).
std::string union_hint(const RepairOptions& repair) {
  if (!repair.enabled) return "; \"repair\": true joins overlapping parts into one surface (their union)";
  if (repair.parts != PartsPolicy::Union)
    return "; \"parts\": \"union\" (the default of \"repair\") joins overlapping parts into one surface";
  return "";
}

// Notes on a closed mesh that is still suspect: several closed parts (one gas volume for all of them),
// surfaces that touch at a vertex only, and surfaces that pass through each other.
void note_suspicious_shapes(const TriMesh& mesh, const RepairOptions& repair, std::vector<std::string>& notes) {
  const MeshParts parts = edge_connected_parts(mesh);
  if (parts.count > 1) {
    std::vector<int> triangles(static_cast<std::size_t>(parts.count), 0);
    for (int p : parts.part_of_triangle) ++triangles[static_cast<std::size_t>(p)];
    std::string sizes;
    for (std::size_t p = 0; p < triangles.size() && p < 8; ++p) sizes += (p ? ", " : "") + std::to_string(triangles[p]);
    if (triangles.size() > 8) sizes += ", ...";
    notes.push_back(
        "holds " + std::to_string(parts.count) + " separate closed parts (" + sizes +
        " triangles), simulated as one body whose gas fills all of them as one volume (\"split\": true on the "
        "body makes each its own body)");
  }
  const std::vector<int> pinched = pinched_vertices(mesh);
  if (!pinched.empty()) {
    const Vec3& p = mesh.vertices[static_cast<std::size_t>(pinched.front())];
    char where[160];
    std::snprintf(where, sizeof where, " (the first at (%.4g, %.4g, %.4g))", p.x(), p.y(), p.z());
    notes.push_back("has " + std::to_string(pinched.size()) + " vertices where surfaces touch at that vertex only" +
                    where + ": the parts there share one vertex and one gas volume");
  }
  const SelfIntersections crossing = find_self_intersections(mesh);
  if (crossing.pairs > 0) {
    notes.push_back("intersects itself: " + std::to_string(crossing.pairs) + " pairs of triangles cross (the first: " +
                    std::to_string(crossing.first.first) + " and " + std::to_string(crossing.first.second) +
                    "), so the gas volume counts the overlap twice or not at all" +
                    (parts.count > 1 ? union_hint(repair) : ""));
  }
}

// What the repair step that fixes `defect` does, or "" where repair has no step for it.
std::string repair_action(MeshDefect defect) {
  switch (defect) {
    case MeshDefect::Open: return "fill the holes";
    case MeshDefect::NonManifold: return "split the non-manifold edges";
    case MeshDefect::Winding: return "orient the faces consistently";
    case MeshDefect::Degenerate: return "remove the degenerate faces";
    case MeshDefect::TooSmall:
    case MeshDefect::NoVolume: return "";
  }
  return "";
}

}  // namespace

std::string repair_hint(MeshDefect defect, const RepairOptions& repair, const std::filesystem::path& file,
                        const std::vector<std::string>& repair_notes) {
  const std::string action = repair_action(defect);
  if (action.empty()) return "";
  if (!repair.enabled) {
    return "; add \"repair\": true to the body to " + action + " (or write a repaired copy: softbody prepare " +
           softbody::one_line(file.string()) + " OUT.obj)";
  }
  if (defect == MeshDefect::Open && !repair.holes) return "; repair.holes is false: set it to true to " + action;
  if (defect == MeshDefect::Degenerate && !repair.degenerate)
    return "; repair.degenerate is false: set it to true to " + action;
  if (repair_notes.empty()) return "; still so after \"repair\", which changed nothing";
  std::string done = "; still so after \"repair\", which did: ";
  for (std::size_t i = 0; i < repair_notes.size(); ++i) done += (i ? "; " : "") + repair_notes[i];
  return done;
}

LoadedMesh load_closed_mesh(const std::string& spec, const std::filesystem::path& file, const std::string& context,
                            const MeshLimits& limits, const Repair& repair, const softbody::AfterPhase& after_phase) {
  const std::string what = softbody::one_line(file.empty() ? spec : file.string());
  const auto phase_done = [&](const std::string& phase) {
    if (after_phase) after_phase(phase + " " + what);
  };
  // A stop request while assimp reads ends the wait for it (assimp cannot be asked to stop).
  const auto while_reading = [&] { phase_done("reading part of"); };
  try {
    LoadedMesh loaded;
    loaded.mesh = file.empty() ? generate(spec) : weld(import_mesh_file(file, limits, while_reading));
    phase_done(file.empty() ? "generating" : "reading");
    if (!file.empty() && repair.options.enabled) {
      if (!repair.step) throw std::logic_error("load_closed_mesh: repair asked for without a repair step");
      RepairedMesh repaired = repair.step(loaded.mesh, repair.options);
      loaded.mesh = std::move(repaired.mesh);
      loaded.notes = std::move(repaired.notes);
      phase_done("repairing");
    }
    try {
      validate_closed(loaded.mesh, loaded.notes);
    } catch (const MeshDefectError& e) {
      if (file.empty()) throw;
      throw softbody::InputError(e.what() + repair_hint(e.defect(), repair.options, file, loaded.notes));
    }
    if (!file.empty()) note_suspicious_shapes(loaded.mesh, repair.options, loaded.notes);
    phase_done("checking");
    for (std::string& note : loaded.notes) note = context + ": " + what + ": " + note;
    return loaded;
  } catch (const softbody::InputError& e) {
    throw softbody::InputError(context + ": mesh " + what + " " + e.what());
  }
}

}  // namespace mesh
