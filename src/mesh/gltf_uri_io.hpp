// assimp's file access for a glTF file: a buffer's uri is a URI (RFC 3986), so the file it names is opened by
// its percent-decoded name ("cube%2Ebin" opens cube.bin), the name check_referenced_uri checked.
#pragma once

#include <string>

#include <assimp/DefaultIOSystem.h>

namespace mesh {

class GltfUriIoSystem final : public Assimp::DefaultIOSystem {
 public:
  // `gltf_file`: the path assimp is asked to read, which is opened as it is.
  explicit GltfUriIoSystem(std::string gltf_file);

  using Assimp::DefaultIOSystem::Exists;
  using Assimp::DefaultIOSystem::Open;
  bool Exists(const char* file) const override;
  Assimp::IOStream* Open(const char* file, const char* mode) override;

 private:
  // A file in the glTF file's folder (assimp names it folder + uri) with its uri part decoded; others as they are.
  std::string decoded(const char* file) const;

  std::string gltf_file_;
  std::string folder_;  // up to and including the last '/' or '\' of gltf_file_, as assimp's glTF readers cut it
};

}  // namespace mesh
