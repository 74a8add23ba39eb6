// FBX object connections checked before assimp reads the file: assimp 5.2's FBX converter walks the object
// hierarchy recursively from the root and trusts the file's "Connections" section, so an object connected to
// itself (found by fuzz_mesh_fbx: `C: "OO", 1000003, 1000003`) or a longer cycle recursed until the stack ran
// out (SIGSEGV), and so would a chain nested deeper than the stack allows.
#pragma once

#include <string_view>

namespace mesh {

// The deepest chain of object connections a file may hold (a character rig is a few dozen levels deep).
inline constexpr int kMostFbxConnectionLevels = 1000;

// True when `head` starts a binary FBX file ("Kaydara FBX Binary").
bool looks_like_binary_fbx(std::string_view head);

// Throws softbody::InputError (message without the file name) if the connections of `file_text`, a whole FBX file
// (binary, or ASCII when it does not start as binary FBX does), form a cycle or a chain of more than
// kMostFbxConnectionLevels objects. A file whose records cannot be followed is left to assimp, which reports it.
void check_fbx_connections(std::string_view file_text);

}  // namespace mesh
