// Mesh repair: polygon soup clean-up and orientation, stitching, degenerate faces, hole filling, parts (kept,
// the largest, or the overlapping ones joined by a Boolean union), outward winding.
#include "geometry/mesh_repair.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <iterator>
#include <numeric>
#include <optional>
#include <set>
#include <string_view>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include "geometry/cgal_surface.hpp"
#include "geometry/uv_transfer.hpp"

namespace geometry {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Polygon = std::vector<std::size_t>;
using Face = SurfaceMesh::Face_index;
using Halfedge = SurfaceMesh::Halfedge_index;

// The pieces of a note end to end (a fold of += rather than "text" + std::string, which GCC 12's -Wrestrict
// misreads).
std::string cat(std::initializer_list<std::string_view> pieces) {
  std::string text;
  for (std::string_view piece : pieces) text += piece;
  return text;
}

std::string count_of(std::size_t n, const char* one, const char* many) {
  return cat({std::to_string(n), " ", n == 1 ? one : many});
}

// A polygon soup: the mesh's points and faces as index lists, before any connectivity is assumed.
struct Soup {
  std::vector<Point> points;
  std::vector<Polygon> polygons;
};

Soup soup_of(const mesh::TriMesh& mesh) {
  Soup soup;
  soup.points.reserve(mesh.vertices.size());
  for (const mesh::Vec3& x : mesh.vertices) soup.points.emplace_back(x.x(), x.y(), x.z());
  soup.polygons.reserve(mesh.triangles.size());
  for (const mesh::Triangle& t : mesh.triangles) {
    soup.polygons.push_back(
        {static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2])});
  }
  return soup;
}

// Step 1: faces with a repeated vertex and faces over the same three vertices as an earlier one (in either
// winding) are removed, with the points no face uses (PMP::repair_polygon_soup, which does all three).
void remove_soup_degeneracies(Soup& soup, std::vector<std::string>& notes) {
  std::size_t repeated = 0;
  std::vector<std::array<std::size_t, 3>> sorted;
  sorted.reserve(soup.polygons.size());
  for (const Polygon& p : soup.polygons) {
    if (p[0] == p[1] || p[1] == p[2] || p[2] == p[0]) {
      ++repeated;
      continue;
    }
    std::array<std::size_t, 3> key{p[0], p[1], p[2]};
    std::sort(key.begin(), key.end());
    sorted.push_back(key);
  }
  std::sort(sorted.begin(), sorted.end());
  const std::size_t distinct =
      static_cast<std::size_t>(std::distance(sorted.begin(), std::unique(sorted.begin(), sorted.end())));
  const std::size_t duplicates = sorted.size() - distinct;
  if (repeated == 0 && duplicates == 0) return;
  PMP::repair_polygon_soup(soup.points, soup.polygons);
  std::string note = "repair: removed";
  if (repeated > 0) note += cat({" ", count_of(repeated, "face", "faces"), " with a repeated vertex"});
  if (repeated > 0 && duplicates > 0) note += " and";
  if (duplicates > 0)
    note +=
        cat({" ", count_of(duplicates, "duplicate face", "duplicate faces"), " (the same three vertices as another)"});
  notes.push_back(note);
}

// What PMP::orient_polygon_soup reports while it makes the soup a manifold with one winding per part.
struct OrientationCounts {
  std::size_t non_manifold_edges = 0;
  std::size_t non_manifold_vertices = 0;
  std::size_t duplicated_vertices = 0;
  std::size_t reversed_faces = 0;
};

// Copied by value into the orienter: the counts live with the caller. A non-manifold edge is reported once per
// face on it; the set counts it once.
struct OrientationVisitor : PMP::Default_orientation_visitor {
  OrientationCounts* counts;
  std::set<std::pair<std::size_t, std::size_t>>* edges;
  OrientationVisitor(OrientationCounts* c, std::set<std::pair<std::size_t, std::size_t>>* e) : counts(c), edges(e) {}
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t) {
    if (edges->insert({std::min(a, b), std::max(a, b)}).second) ++counts->non_manifold_edges;
  }
  void non_manifold_vertex(std::size_t, std::size_t) { ++counts->non_manifold_vertices; }
  void duplicated_vertex(std::size_t, std::size_t) { ++counts->duplicated_vertices; }
  void polygon_orientation_reversed(std::size_t) { ++counts->reversed_faces; }
};

// Step 2: edges with three or more faces and vertices where surfaces touch at a point get their own copies of
// the vertices for each sheet, and faces are reversed until every edge is traversed once each way.
void orient_soup(Soup& soup, std::vector<std::string>& notes) {
  OrientationCounts counts;
  std::set<std::pair<std::size_t, std::size_t>> edges;
  PMP::orient_polygon_soup(soup.points, soup.polygons, CGAL::parameters::visitor(OrientationVisitor(&counts, &edges)));
  if (counts.non_manifold_edges > 0 || counts.non_manifold_vertices > 0) {
    const std::string edge_words =
        cat({count_of(counts.non_manifold_edges, "non-manifold edge", "non-manifold edges"), " (three or more faces)"});
    const std::string vertex_words =
        cat({count_of(counts.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices"),
             " (surfaces touching at a point)"});
    const bool both = counts.non_manifold_edges > 0 && counts.non_manifold_vertices > 0;
    notes.push_back(cat({"repair: split ", counts.non_manifold_edges > 0 ? edge_words : "", both ? " and " : "",
                         counts.non_manifold_vertices > 0 ? vertex_words : "", " into separate sheets: ",
                         count_of(counts.duplicated_vertices, "vertex", "vertices"), " duplicated"}));
  }
  if (counts.reversed_faces > 0) {
    notes.push_back(cat({"repair: reversed ", count_of(counts.reversed_faces, "face", "faces"),
                         " so that each part is wound one way (every edge traversed once in each direction)"}));
  }
}

// Step 3: border edges whose end points coincide with another border edge's are joined (the weld merged
// coincident vertices already; what stays is where the soup's orientation had to cut).
void stitch(SurfaceMesh& surface, std::vector<std::string>& notes) {
  const std::size_t stitched = PMP::stitch_borders(surface);
  const std::size_t split = PMP::duplicate_non_manifold_vertices(surface);
  if (stitched > 0)
    notes.push_back(
        cat({"repair: stitched ", count_of(stitched, "pair", "pairs"), " of border edges with matching end points"}));
  if (split > 0)
    notes.push_back(
        cat({"repair: split ", count_of(split, "non-manifold vertex", "non-manifold vertices"), " left by stitching"}));
}

std::size_t degenerate_face_count(const SurfaceMesh& surface) {
  std::size_t count = 0;
  for (Face f : surface.faces()) count += PMP::is_degenerate_triangle_face(f, surface) ? 1 : 0;
  return count;
}

// Step 4: faces whose three points are collinear (exact predicate) go by edge collapses and flips
// (PMP::remove_degenerate_faces), which keep the surface closed where it was.
void remove_degenerate_faces(SurfaceMesh& surface, std::vector<std::string>& notes) {
  const std::size_t degenerate = degenerate_face_count(surface);
  if (degenerate == 0) return;
  const std::size_t faces_before = surface.number_of_faces();
  const bool all_removed = PMP::remove_degenerate_faces(surface);
  surface.collect_garbage();
  const std::size_t left = all_removed ? 0 : degenerate_face_count(surface);
  const std::size_t fewer = faces_before - surface.number_of_faces();
  notes.push_back(
      cat({"repair: removed ", count_of(degenerate - left, "zero-area face", "zero-area faces"),
           " (collinear corners) by edge flips and collapses (", count_of(fewer, "face", "faces"), " fewer)",
           left > 0 ? cat({"; ", std::to_string(left), " could not be removed"}) : std::string()}));
}

struct HoleCounts {
  std::size_t holes = 0, edges = 0, smallest = 0, largest = 0;  // edges: around all holes
  std::size_t faces = 0, vertices = 0;                          // added
  std::size_t unfaired = 0, unfilled = 0;
};

std::size_t border_edge_count(const SurfaceMesh& surface, Halfedge h) {
  std::size_t n = 0;
  for ([[maybe_unused]] Halfedge e : CGAL::halfedges_around_face(h, surface)) ++n;
  return n;
}

// Step 5: every border cycle is triangulated (minimum-weight, Liepa 2003), refined to the density around it,
// and faired (a harmonic-like membrane with C¹ continuity to its rim); where the fairing's linear solve fails,
// the refined triangulation stays.
void fill_holes(SurfaceMesh& surface, std::vector<std::string>& notes) {
  std::vector<Halfedge> borders;
  PMP::extract_boundary_cycles(surface, std::back_inserter(borders));
  if (borders.empty()) return;
  HoleCounts counts;
  counts.smallest = static_cast<std::size_t>(-1);
  for (Halfedge h : borders) {
    const std::size_t edges = border_edge_count(surface, h);
    ++counts.holes;
    counts.edges += edges;
    counts.smallest = std::min(counts.smallest, edges);
    counts.largest = std::max(counts.largest, edges);
    std::vector<Face> faces;
    std::vector<SurfaceMesh::Vertex_index> vertices;
    const auto result =
        PMP::triangulate_refine_and_fair_hole(surface, h, std::back_inserter(faces), std::back_inserter(vertices));
    counts.faces += faces.size();
    counts.vertices += vertices.size();
    if (faces.empty()) {
      ++counts.unfilled;
    } else if (!std::get<0>(result)) {
      ++counts.unfaired;
    }
  }
  std::string note = cat({"repair: filled ", count_of(counts.holes - counts.unfilled, "hole", "holes"), " of "});
  note += counts.smallest == counts.largest
              ? std::to_string(counts.largest)
              : cat({std::to_string(counts.smallest), "..", std::to_string(counts.largest)});
  note += cat({" edges (", std::to_string(counts.edges), " boundary edges) with ",
               count_of(counts.faces, "triangle", "triangles"), " and ",
               count_of(counts.vertices, "new vertex", "new vertices"), ", refined and faired"});
  if (counts.unfaired > 0)
    note += cat({"; ", std::to_string(counts.unfaired), " of them not faired (the fairing solve failed): left flat"});
  if (counts.unfilled > 0)
    note += cat({"; ", count_of(counts.unfilled, "hole", "holes"), " could not be triangulated"});
  notes.push_back(note);
}

// Step 6 ("parts": "largest"): only the edge-connected part with the most faces stays.
void keep_largest_part(SurfaceMesh& surface, std::vector<std::string>& notes) {
  const std::size_t faces_before = surface.number_of_faces();
  const std::size_t removed = PMP::keep_largest_connected_components(surface, 1);
  if (removed == 0) return;
  surface.collect_garbage();
  notes.push_back(cat({"repair: kept the largest of ", std::to_string(removed + 1), " parts (",
                       std::to_string(surface.number_of_faces()), " of ", std::to_string(faces_before), " faces)"}));
}

// 6V = Σ p_a·(p_b × p_c) of each edge-connected part (the divergence theorem; > 0 for a closed part wound
// outward), and the part of each face.
struct PartVolumes {
  std::vector<double> six_volume;
  std::vector<std::size_t> part_of_face;  // by face index
};

PartVolumes part_volumes(SurfaceMesh& surface) {
  auto part_of = surface.add_property_map<Face, std::size_t>("f:softbody_part", 0).first;
  PartVolumes volumes;
  volumes.six_volume.assign(PMP::connected_components(surface, part_of), 0.0);
  volumes.part_of_face.assign(surface.num_faces(), 0);
  for (Face f : surface.faces()) {
    const Halfedge h = surface.halfedge(f);
    const Point& a = surface.point(surface.source(h));
    const Point& b = surface.point(surface.target(h));
    const Point& c = surface.point(surface.target(surface.next(h)));
    volumes.six_volume[part_of[f]] += CGAL::determinant(a - CGAL::ORIGIN, b - CGAL::ORIGIN, c - CGAL::ORIGIN);
    volumes.part_of_face[static_cast<std::size_t>(f)] = part_of[f];
  }
  surface.remove_property_map(part_of);
  return volumes;
}

// The bounding box's diagonal [mesh units].
double diagonal_of(const SurfaceMesh& surface) {
  const CGAL::Bbox_3 box = PMP::bbox(surface);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

// Step 6b: closed parts that enclose no volume (|V| below 1e-12 of the diagonal cubed, validation's own
// threshold: two triangles back to back, a fin whose hole the filling closed with its own mirror image).
void remove_flat_parts(SurfaceMesh& surface, std::vector<std::string>& notes) {
  if (surface.is_empty() || !CGAL::is_closed(surface)) return;
  const PartVolumes volumes = part_volumes(surface);
  if (volumes.six_volume.size() < 2) return;
  const double diagonal = diagonal_of(surface);
  const double flat = 6.0 * 1e-12 * diagonal * diagonal * diagonal;
  std::vector<Face> doomed;
  for (Face f : surface.faces()) {
    if (std::abs(volumes.six_volume[volumes.part_of_face[static_cast<std::size_t>(f)]]) <= flat) doomed.push_back(f);
  }
  const std::size_t parts = static_cast<std::size_t>(std::count_if(volumes.six_volume.begin(), volumes.six_volume.end(),
                                                                   [&](double v) { return std::abs(v) <= flat; }));
  if (doomed.empty() || parts == volumes.six_volume.size()) return;  // never remove everything
  for (Face f : doomed) CGAL::Euler::remove_face(surface.halfedge(f), surface);
  surface.collect_garbage();
  notes.push_back(cat({"repair: removed ", count_of(parts, "flat part", "flat parts"), " (",
                       count_of(doomed.size(), "face", "faces"), ") that enclose no volume (sheets back to back)"}));
}

// Step 7: each closed edge-connected part whose signed volume 6V = Σ p_a·(p_b × p_c) is negative faces inward:
// its faces are reversed. (A part nested in another is turned outward too: one gas fills every part.)
void orient_parts_outward(SurfaceMesh& surface, std::vector<std::string>& notes) {
  if (surface.is_empty() || !CGAL::is_closed(surface)) return;
  const PartVolumes volumes = part_volumes(surface);
  std::vector<Face> inward;
  for (Face f : surface.faces()) {
    if (volumes.six_volume[volumes.part_of_face[static_cast<std::size_t>(f)]] < 0.0) inward.push_back(f);
  }
  const std::size_t parts = volumes.six_volume.size();
  const std::size_t inward_parts = static_cast<std::size_t>(
      std::count_if(volumes.six_volume.begin(), volumes.six_volume.end(), [](double v) { return v < 0.0; }));
  if (inward.empty()) return;
  PMP::reverse_face_orientations(inward, surface);
  notes.push_back(cat({"repair: turned ", count_of(inward_parts, "inside-out part", "inside-out parts"), " of ",
                       std::to_string(parts), " outward (", count_of(inward.size(), "face", "faces"), " reversed)"}));
}

// The groups of parts that overlap, touch or nest (PMP::do_intersect on closed meshes: faces that meet, or one
// part's bounded side inside another's), by union-find over the pairs whose bounding boxes meet; each group
// lists its parts in increasing order, groups in the order of their first part.
std::vector<std::vector<std::size_t>> overlapping_groups(const std::vector<SurfaceMesh>& parts) {
  std::vector<std::size_t> root(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) root[i] = i;
  const auto find = [&](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  std::vector<CGAL::Bbox_3> boxes;
  for (const SurfaceMesh& part : parts) boxes.push_back(PMP::bbox(part));
  for (std::size_t i = 0; i < parts.size(); ++i) {
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      if (find(i) == find(j) || !CGAL::do_overlap(boxes[i], boxes[j])) continue;
      const bool meet = PMP::do_intersect(parts[i], parts[j], CGAL::parameters::do_overlap_test_of_bounded_sides(true),
                                          CGAL::parameters::do_overlap_test_of_bounded_sides(true));
      if (meet) root[std::max(find(i), find(j))] = std::min(find(i), find(j));
    }
  }
  std::vector<std::vector<std::size_t>> groups(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) groups[find(i)].push_back(i);
  groups.erase(std::remove_if(groups.begin(), groups.end(), [](const auto& g) { return g.empty(); }), groups.end());
  return groups;
}

// The same surface with its vertices in lexicographic order of their coordinates and its faces, each starting
// at its smallest vertex (the winding kept), in lexicographic order. CGAL's corefinement orders its output by
// where the heap put its internal boxes: the teapot, read from a file of another name or with a no-op --set,
// came out of the union with its vertices in another order, and its proxy's remesh with another vertex count.
// In this order the union's result depends on the surfaces alone (vertices at exactly the same point keep the
// order they came in).
SurfaceMesh in_canonical_order(const SurfaceMesh& surface) {
  const mesh::TriMesh given = to_trimesh(surface);
  std::vector<std::size_t> order(given.vertices.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const mesh::Vec3& p = given.vertices[a];
    const mesh::Vec3& q = given.vertices[b];
    return std::array<double, 3>{p.x(), p.y(), p.z()} < std::array<double, 3>{q.x(), q.y(), q.z()};
  });
  std::vector<int> rank(order.size());
  mesh::TriMesh sorted;
  sorted.vertices.reserve(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    rank[order[i]] = static_cast<int>(i);
    sorted.vertices.push_back(given.vertices[order[i]]);
  }
  sorted.triangles.reserve(given.triangles.size());
  for (const mesh::Triangle& t : given.triangles) {
    mesh::Triangle renumbered{rank[static_cast<std::size_t>(t[0])], rank[static_cast<std::size_t>(t[1])],
                              rank[static_cast<std::size_t>(t[2])]};
    std::rotate(renumbered.begin(), std::min_element(renumbered.begin(), renumbered.end()), renumbered.end());
    sorted.triangles.push_back(renumbered);
  }
  std::sort(sorted.triangles.begin(), sorted.triangles.end());
  return to_surface_mesh(sorted);
}

// The Boolean union of the group's parts, one after the other (PMP::corefine_and_compute_union: the
// surfaces cut along their intersection curves, the pieces inside another part dropped). Empty where it
// cannot be computed: a part that intersects itself (corefinement needs each input free of self-crossings),
// or a result that is not a closed manifold.
std::optional<SurfaceMesh> union_of(std::vector<SurfaceMesh>& parts, const std::vector<std::size_t>& group) {
  for (std::size_t p : group) {
    if (PMP::does_self_intersect(parts[p])) return std::nullopt;
  }
  SurfaceMesh joined = parts[group.front()];
  for (std::size_t k = 1; k < group.size(); ++k) {
    SurfaceMesh next = parts[group[k]];
    SurfaceMesh result;
    if (!PMP::corefine_and_compute_union(joined, next, result)) return std::nullopt;
    joined = std::move(result);
  }
  joined.collect_garbage();
  if (!CGAL::is_closed(joined)) return std::nullopt;
  return in_canonical_order(joined);
}

// Step 8 ("parts": "union", the default): closed parts that overlap, touch or lie inside one another become
// one closed surface, their union: one gas volume that counts every point inside once (the teapot's spout,
// handle and lid passing into its body). Parts apart from all others are left as they are; where nothing
// overlaps, the surface is not touched at all.
void union_overlapping_parts(SurfaceMesh& surface, std::vector<std::string>& notes) {
  if (surface.is_empty() || !CGAL::is_closed(surface)) return;
  std::vector<SurfaceMesh> parts;
  PMP::split_connected_components(surface, parts);
  if (parts.size() < 2) return;
  const std::vector<std::vector<std::size_t>> groups = overlapping_groups(parts);
  if (groups.size() == parts.size()) return;
  SurfaceMesh rebuilt;
  std::size_t merged = 0, surfaces = 0, failed = 0, parts_now = 0;
  for (const std::vector<std::size_t>& group : groups) {
    if (group.size() == 1) {
      rebuilt.join(parts[group.front()]);
      ++parts_now;
      continue;
    }
    if (std::optional<SurfaceMesh> joined = union_of(parts, group)) {
      merged += group.size();
      ++surfaces;
      ++parts_now;
      rebuilt.join(*joined);
    } else {
      failed += group.size();
      parts_now += group.size();
      for (std::size_t p : group) rebuilt.join(parts[p]);
    }
  }
  if (merged > 0) {
    surface = std::move(rebuilt);
    notes.push_back(
        cat({"repair: joined ", std::to_string(merged), " overlapping parts into ",
             count_of(surfaces, "surface", "surfaces"), " (their Boolean union, PMP::corefine_and_compute_union); ",
             count_of(static_cast<std::size_t>(surface.number_of_faces()), "face", "faces"), ", ",
             count_of(parts_now, "part", "parts"), " now"}));
  }
  if (failed > 0) {
    notes.push_back(
        cat({"repair: could not join ", std::to_string(failed),
             " overlapping parts (one of them intersects itself, or their union is not closed): kept as they are"}));
  }
}

// Vertices no triangle uses (left where faces were removed) dropped, the others kept in order.
mesh::TriMesh without_unused_vertices(mesh::TriMesh m) {
  std::vector<int> renumbered(m.vertices.size(), -1);
  for (const mesh::Triangle& t : m.triangles) {
    for (int v : t) renumbered[static_cast<std::size_t>(v)] = 0;
  }
  std::size_t kept = 0;
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    if (renumbered[v] < 0) continue;
    renumbered[v] = static_cast<int>(kept);
    m.vertices[kept++] = m.vertices[v];
  }
  m.vertices.resize(kept);
  for (mesh::Triangle& t : m.triangles) {
    for (int& v : t) v = renumbered[static_cast<std::size_t>(v)];
  }
  return m;
}

}  // namespace

RepairedMesh repair_mesh(const mesh::TriMesh& welded, const mesh::RepairOptions& options) {
  RepairedMesh repaired;
  std::vector<std::string>& notes = repaired.notes;
  Soup soup = soup_of(welded);
  if (options.degenerate) remove_soup_degeneracies(soup, notes);
  orient_soup(soup, notes);
  SurfaceMesh surface;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, surface);
  stitch(surface, notes);
  if (options.degenerate) remove_degenerate_faces(surface, notes);
  if (options.holes) fill_holes(surface, notes);
  if (options.degenerate && options.holes) remove_degenerate_faces(surface, notes);  // a filled hole's slivers
  if (options.degenerate) remove_flat_parts(surface, notes);
  if (options.parts == mesh::PartsPolicy::Largest) keep_largest_part(surface, notes);
  orient_parts_outward(surface, notes);
  if (options.parts == mesh::PartsPolicy::Union) union_overlapping_parts(surface, notes);
  repaired.mesh = without_unused_vertices(to_trimesh(surface));
  repaired.mesh.corner_uvs = transfer_corner_uvs(welded, repaired.mesh);  // empty where the file had none
  if (notes.empty()) notes.push_back("repair: nothing to repair");
  return repaired;
}

}  // namespace geometry
