// Accepted mesh formats: an extension list checked before reading, and assimp's other readers removed.
#include "mesh/mesh_formats.hpp"

#include <array>
#include <cctype>
#include <sstream>
#include <string_view>

#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>

#include "core/errors.hpp"
#include "core/one_line.hpp"

namespace mesh {
namespace {

// The extensions of the documented formats (docs/guide/meshes.md), without their dot.
constexpr std::array<std::string_view, 7> kAcceptedExtensions{"obj", "ply", "stl", "gltf", "glb", "off", "fbx"};

// assimp's name for its glTF 1.0 reader (its glTF 2.0 reader is "glTF2 Importer").
constexpr std::string_view kGltf1ReaderName{"glTF Importer"};

constexpr std::string_view kAcceptedWords{
    "OBJ, PLY, STL, glTF, OFF or FBX: a name ending in .obj, .ply, .stl, .gltf, .glb, .off or .fbx"};

bool is_accepted(std::string_view extension_without_dot) {
  for (const std::string_view accepted : kAcceptedExtensions) {
    if (extension_without_dot == accepted) return true;
  }
  return false;
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

std::string lower_case_extension(const std::filesystem::path& file) { return lower(file.extension().string()); }

void check_format_is_accepted(const std::filesystem::path& file) {
  const std::string extension = lower_case_extension(file);
  if (extension.size() > 1 && is_accepted(std::string_view(extension).substr(1))) return;
  if (extension.empty()) {
    throw softbody::InputError("has no file name extension, so its format is unknown (expected " +
                               std::string(kAcceptedWords) + ")");
  }
  throw softbody::InputError("is a " + softbody::one_line(extension.substr(0, 40)) +
                             " file, a format softbody does not read (expected " + std::string(kAcceptedWords) + ")");
}

void keep_only_accepted_readers(Assimp::Importer& importer) {
  for (std::size_t i = importer.GetImporterCount(); i-- > 0;) {
    const aiImporterDesc* description = importer.GetImporterInfo(i);
    bool accepted = false;
    std::istringstream extensions(description != nullptr ? description->mFileExtensions : "");
    for (std::string extension; extensions >> extension;) accepted = accepted || is_accepted(lower(extension));
    // glTF 1.0 shares .gltf with glTF 2.0 but is not read (mesh/gltf_check.cpp says why).
    if (accepted && description != nullptr && std::string_view(description->mName) == kGltf1ReaderName)
      accepted = false;
    if (accepted) continue;
    Assimp::BaseImporter* reader = importer.GetImporter(i);
    // UnregisterLoader only takes the reader off the list; the importer would otherwise leak it.
    if (importer.UnregisterLoader(reader) == aiReturn_SUCCESS) delete reader;
  }
}

}  // namespace mesh
