// PLY triangle strips as faces: assimp 5.2 reads a "tristrips" element wrongly (the Igea scan of 134,345
// vertices came out as one triangle), so the loader hands it a copy of the file with the strips turned into a
// "face" element of triangles.
#pragma once

#include <string>
#include <string_view>

namespace mesh {

// The PLY file `whole` (header and body) with its "tristrips" element (one list property of vertex indices,
// -1 between strips) replaced by a "face" element of the strips' triangles, in the same format (ascii or
// binary, either byte order) and with every other element's rows as they were; "" when the file has no such
// element or cannot be walked (check_ply_header then refuses it with its own words). A strip v0 v1 v2 v3 ...
// gives (v0, v1, v2), (v2, v1, v3), (v2, v3, v4), ...: every other triangle reversed, so that all keep the
// strip's winding; triangles with a repeated vertex (a strip's joins) are left out.
// Throws softbody::InputError when the strips hold more than `max_triangles` triangles (limits.max_triangles).
std::string faces_from_strips(std::string_view whole, long long max_triangles);

}  // namespace mesh
