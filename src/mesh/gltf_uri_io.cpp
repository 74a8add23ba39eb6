// Percent-decoded buffer files for assimp's glTF readers.
#include "mesh/gltf_uri_io.hpp"

#include <utility>

#include "core/errors.hpp"
#include "mesh/file_references.hpp"

namespace mesh {

GltfUriIoSystem::GltfUriIoSystem(std::string gltf_file) : gltf_file_(std::move(gltf_file)) {
  const std::size_t slash = gltf_file_.find_last_of("/\\");
  folder_ = slash == std::string::npos ? "" : gltf_file_.substr(0, slash + 1);
}

std::string GltfUriIoSystem::decoded(const char* file) const {
  const std::string path(file);
  if (path == gltf_file_ || path.compare(0, folder_.size(), folder_) != 0) return path;
  try {
    return folder_ + percent_decoded(std::string_view(path).substr(folder_.size()), "uri");
  } catch (const softbody::InputError&) {
    return path;  // refused before assimp read the file (check_referenced_uri); opened as written if asked again
  }
}

bool GltfUriIoSystem::Exists(const char* file) const { return DefaultIOSystem::Exists(decoded(file).c_str()); }

Assimp::IOStream* GltfUriIoSystem::Open(const char* file, const char* mode) {
  return DefaultIOSystem::Open(decoded(file).c_str(), mode);
}

}  // namespace mesh
