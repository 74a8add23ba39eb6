// PLY headers checked before assimp reads the file: assimp trusts a header's counts (it reserves what
// the header announces, and loops on some malformed headers), so counts, types and the body's size are
// checked here first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "mesh/mesh_limits.hpp"

namespace mesh {

// True when `head` (the file's first bytes) starts with "ply", the magic word assimp recognises PLY files by
// (whatever follows: a malformed first line is refused by check_ply_header, not passed to assimp).
bool looks_like_ply(std::string_view head);

// Throws softbody::InputError (message without the file name) unless `head`, which holds the whole header
// and the whole body (every value of an ASCII body a number; every list's count within what is left of the
// file; every face of at least 3 vertices),
// is a well-formed PLY header: format ascii / binary_little_endian / binary_big_endian 1.0, every element
// with a decimal count and at least one property of a known type, list counts of an integer type, an
// end_header line; vertex and face counts within `limits`; and a body (file_bytes minus the header) large
// enough to hold what the header announces.
// Returns where assimp must be given one extra line feed (std::string_view::npos: nowhere): right after the
// header of a binary file whose header ends with a plain LF and whose data starts with the byte 0x0A. assimp 5.2
// drops a 0x0A that starts binary data (meant for the LF of an "end_header" CR LF) and would read every value
// one byte off; with one more LF there, it drops that one and reads the data as written.
std::size_t check_ply_header(std::string_view head, std::uintmax_t file_bytes, const MeshLimits& limits);

// True when `head` starts an OFF file ("OFF", "COFF", "NOFF", ... then whitespace).
bool looks_like_off(std::string_view head);

// The same for OFF (its "OFF" keyword optional): the vertex and face counts within `limits`, and a body large
// enough for them.
void check_off_header(std::string_view head, std::uintmax_t file_bytes, const MeshLimits& limits);

}  // namespace mesh
