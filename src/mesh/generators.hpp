// Built-in closed meshes: "icosphere:L" (unit sphere), "cube:N" (unit cube, N×N quads a side),
// "torus:M,N" (ring radius 1, tube radius 0.4), "capsule:N" (radius 0.5, 2 m tall along y), "tube:N,L" (radius 0.5,
// a cylinder of L m along y between two hemispheres).
#pragma once

#include <string>

#include "mesh/trimesh.hpp"

namespace mesh {

// True when `spec` names a built-in generator ("icosphere:...", "cube:...", "torus:...", "capsule:...").
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

// Torus around the y axis: `ring_segments` around the ring, `tube_segments` around the tube.
TriMesh torus(int ring_segments, int tube_segments);

// Capsule along y: two hemispheres of radius 0.5 joined by a cylinder of length 1; `segments` around.
TriMesh capsule(int segments);

// A long capsule along y: radius 0.5, a cylinder of `length` m between the hemispheres, with rings along it about
// as far apart as its vertices around (so that it bends smoothly); `segments` around.
TriMesh tube(int segments, int length);

}  // namespace mesh
