// Bending resistance by links: a spring between the two vertices opposite each interior edge (the far
// corners of the edge's two triangles), resting at its length in the placed mesh.
//
// Why links and not dihedral-angle springs (Bridson, Marino & Fedkiw 2003): a link is a Hooke spring like
// the edges, so every integrator already has what it needs: the fused force pass (sim/forces/forces.hpp), vbd's
// 3×3 blocks, xpbd's distance
// constraint, the stability estimate's power iterations. Folding the hinge (i, j | a, b) by an angle δ away
// from its rest dihedral θ0 changes the link length by δ · h_a h_b sin θ0 / L_ab (h: the heights of the two
// triangles over the edge), so its bending stiffness is k_b (h_a h_b sin θ0 / L_ab)² [N·m/rad] per link:
// strong where the mesh is curved (ears, horns, a dent), vanishing on a flat hinge (θ0 = π), where the link
// length changes only at second order in δ. That is the price of the cheap form: on a flat patch (a cube's
// faces) the links hold the fold only at second order, where the curved parts of a shape, which are what is
// lost without bending, are held at first order. A link also resists in-plane shear of the quad
// (i, a, j, b), which adds to the edges' stiffness (the stability estimate counts it).
//
// Energy, force (the spring's), unit:  E_b = Σ_links ½ k_b (|x_a − x_b| − ℓ0)²  [J],  k_b in N/m.
// The rest lengths ℓ0 are the placed mesh's, so the mesh is the links' zero-energy shape.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "sim/model/body.hpp"

namespace sim {

// The opposite-vertex pairs of every edge that two triangles of `faces` share, each pair once, a < b, sorted
// (an edge whose two opposite vertices coincide gives none).
std::vector<std::array<int, 2>> bending_links(std::span<const Triangle> faces);

// body.topology.bending_links and body.rest.bending_length_m from the mesh's faces and positions x.
void add_bending_links(Body& body, std::span<const Vec3> x);

// E_b = Σ_links ½ k_b (|x_a − x_b| − ℓ0)² [J] (0 without links): body.constraints' links, so a body of a model.
double bending_energy(const Body& body, std::span<const Vec3> x);

}  // namespace sim
