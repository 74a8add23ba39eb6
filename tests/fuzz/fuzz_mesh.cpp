// libFuzzer harness for the mesh loader of one format (SOFTBODY_FUZZ_EXTENSION, e.g. ".ply"): the input is
// written to a file of that extension and loaded as a body's mesh is (checks, assimp, weld, validation).
// Only softbody::InputError may come out: any other exception, a crash, a hang or a sanitizer finding is a bug.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/errors.hpp"
#include "mesh/load.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                            ("softbody_fuzz_" + std::to_string(::getpid()) + SOFTBODY_FUZZ_EXTENSION);
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (out == nullptr) return 0;
  std::fwrite(data, 1, size, out);
  std::fclose(out);
  try {
    mesh::load_closed_mesh(file.filename().string(), file, "fuzz");
  } catch (const softbody::InputError&) {
  }
  return 0;
}
