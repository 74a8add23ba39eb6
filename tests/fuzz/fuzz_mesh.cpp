// libFuzzer harness for the mesh loader of one format (SOFTBODY_FUZZ_EXTENSION, e.g. ".ply"): the input is
// written to a file of that extension and loaded as a body's mesh is (checks, assimp, weld, validation).
// ".mtl" fuzzes the files a mesh file names: the input is the material library of a fixed OBJ tetrahedron
// (mtllib), which assimp's OBJ reader parses while it reads the OBJ.
// Only softbody::InputError may come out: any other exception, a crash, a hang or a sanitizer finding is a bug.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/errors.hpp"
#include "mesh/load.hpp"

namespace {

constexpr std::string_view kExtension = SOFTBODY_FUZZ_EXTENSION;
constexpr bool kMaterialLibrary = kExtension == ".mtl";

bool write_file(const std::filesystem::path& file, const void* data, std::size_t size) {
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (out == nullptr) return false;
  std::fwrite(data, 1, size, out);
  return std::fclose(out) == 0;
}

// The OBJ that names the fuzzed material library and uses two of its materials.
std::filesystem::path obj_naming(const std::filesystem::path& library) {
  const std::filesystem::path obj = std::filesystem::path(library).replace_extension(".obj");
  const std::string text = "mtllib " + library.filename().string() +
                           "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl red\nf 1 3 2\nf 1 2 4\nusemtl blue\n"
                           "f 1 4 3\nf 2 3 4\n";
  write_file(obj, text.data(), text.size());
  return obj;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                            ("softbody_fuzz_" + std::to_string(::getpid()) + SOFTBODY_FUZZ_EXTENSION);
  static const std::filesystem::path mesh_file = kMaterialLibrary ? obj_naming(file) : file;
  if (!write_file(file, data, size)) return 0;
  try {
    mesh::load_closed_mesh(mesh_file.filename().string(), mesh_file, "fuzz");
  } catch (const softbody::InputError&) {
  }
  return 0;
}
