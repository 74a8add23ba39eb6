// FBX files checked before assimp reads them. assimp 5.2's FBX converter walks the object hierarchy
// recursively from the root and trusts the file's "Connections" section, so an object connected to itself
// (found by fuzz_mesh_fbx: `C: "OO", 1000003, 1000003`) or a longer cycle recursed until the stack ran out
// (SIGSEGV), and so would a chain nested deeper than the stack allows; its binary tokenizer and its converter
// abort on ai_asserts at garbled records and at a Model's time property (fuzz_mesh_fbx too).
#pragma once

#include <string_view>

namespace mesh {

// The deepest chain of object connections a file may hold (a character rig is a few dozen levels deep).
inline constexpr int kMostFbxConnectionLevels = 1000;

// True when `head` starts a binary FBX file ("Kaydara FBX Binary").
bool looks_like_binary_fbx(std::string_view head);

// Throws softbody::InputError (message without the file name) unless `file_text`, a whole FBX file (binary, or
// ASCII when it does not start as binary FBX does), is one that assimp 5.2's reader can follow: a binary
// file's records well formed (offsets, property lengths, null records), no Model property of type KTime, and
// object connections without a cycle or a chain of more than kMostFbxConnectionLevels objects.
void check_fbx_file(std::string_view file_text);

}  // namespace mesh
