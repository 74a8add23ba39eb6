// Built-in closed meshes: "icosphere:L" (unit sphere) and "cube:N" (unit cube, N×N quads a side).
#pragma once

#include <string>

#include "mesh/trimesh.hpp"

namespace mesh {

// True when `spec` names a built-in generator ("icosphere:..." or "cube:...").
bool names_generator(const std::string& spec);

// Empty when `spec` is a valid generator spec, otherwise what is expected.
std::string generator_spec_error(const std::string& spec);

// Builds the mesh a valid generator spec names. Throws softbody::InputError for an invalid one.
TriMesh generate(const std::string& spec);

// Icosahedron subdivided `levels` times (each triangle into four), projected onto the unit sphere:
// 10·4^L + 2 vertices, 20·4^L triangles.
TriMesh icosphere(int levels);

// Axis-aligned cube of side 1 centred at the origin, each face split into N×N quads (2 triangles each).
TriMesh cube(int divisions);

}  // namespace mesh
