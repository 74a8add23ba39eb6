// What the mesh repair stage may change on a body's mesh ("repair" on a body; `softbody prepare`).
#pragma once

namespace mesh {

// What to do with separate parts after repair: join the ones that overlap, touch or nest into one surface
// (their Boolean union) and keep the others apart; keep them all as they are (one body, or one body each with
// "split"); or keep only the part with the most triangles (a stray fragment, an eye, a floating speck removed).
enum class PartsPolicy { Union, Keep, Largest };

// "repair": true is every step below with these defaults; "repair": {...} switches single steps off.
// Always done when repair is on (a surface mesh cannot be built without it): non-manifold vertices and edges
// split, the winding made consistent, and each closed part turned to face outward.
struct RepairOptions {
  bool enabled = false;                    // the body asked for repair at all
  bool degenerate = true;                  // remove faces with a repeated vertex, duplicate faces, zero-area faces
  bool holes = true;                       // fill holes: triangulate, refine to the surrounding density, fair
  PartsPolicy parts = PartsPolicy::Union;  // a mesh whose parts are apart is left as Keep leaves it
};

// Every step on: what "repair": true and `softbody prepare` use.
inline RepairOptions full_repair() {
  RepairOptions options;
  options.enabled = true;
  return options;
}

}  // namespace mesh
