// assimp import: refuse what assimp cannot be trusted with, read, triangulate, flatten the node hierarchy,
// collect triangles with every index and coordinate checked.
#include "mesh/import.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <future>
#include <memory>
#include <string>
#include <thread>
#include <utility>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "core/errors.hpp"
#include "core/file_kind.hpp"
#include "core/one_line.hpp"
#include "mesh/fbx_check.hpp"
#include "mesh/file_references.hpp"
#include "mesh/gltf_check.hpp"
#include "mesh/gltf_uri_io.hpp"
#include "mesh/mesh_formats.hpp"
#include "mesh/mtl_check.hpp"
#include "mesh/off_faces.hpp"
#include "mesh/ply_header.hpp"
#include "mesh/ply_strips.hpp"

namespace mesh {
namespace {

using softbody::InputError;

// The first `bytes` bytes of a file (fewer when it is shorter).
std::string head_of(const std::filesystem::path& file, std::uintmax_t bytes) {
  std::ifstream in(file, std::ios::binary);
  std::string head(static_cast<std::size_t>(bytes), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

// A little-endian uint32 at `at` of `bytes` (which holds at least at + 4 bytes).
std::uint32_t read_u32_le(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int k = 3; k >= 0; --k)
    value = (value << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
  return value;
}

// Binary glTF (GLB): a 12-byte header (magic "glTF", version, total length) and chunks of (length, type, data).
// assimp allocates what the lengths announce, so a length past the file's end (a fuzzed 2 kB file announced
// 4 GB) is refused here.
void check_glb_header(std::string_view head, std::uintmax_t file_bytes) {
  if (head.size() < 20) throw InputError("is a binary glTF (GLB) file shorter than its 20-byte header");
  // Only glTF 2's GLB: a .glb without the magic, or of another version, went to assimp's other glTF reader,
  // which read past the end of its buffer (found by fuzz_mesh_glb: a 45-byte file, heap-buffer-overflow).
  if (head.substr(0, 4) != "glTF" || read_u32_le(head, 4) != 2) {
    throw InputError("is not a binary glTF 2 file (expected the magic \"glTF\" and version 2 in its first 8 bytes)");
  }
  const std::uint32_t total = read_u32_le(head, 8), chunk = read_u32_le(head, 12);
  if (total > file_bytes || std::uintmax_t{chunk} + 20 > file_bytes) {
    throw InputError("is a binary glTF (GLB) file whose header announces " + std::to_string(total) +
                     " bytes and a first chunk of " + std::to_string(chunk) + " bytes, but the file has " +
                     std::to_string(file_bytes));
  }
}

// An OBJ element that names vertices (f, p, l: assimp reads any line starting with those letters as one) before
// the file has given a single vertex (v) names none that exists. Refused before assimp sees it: its OBJ reader
// (libassimp5 5.2.5) reads past the end of its line buffer when such a face is the file's only line (found by
// fuzz_mesh_obj: tests/data/hostile/obj_face_only_line.obj).
// Every material library (mtllib) must be a regular file in the OBJ's folder: assimp opens it (a FIFO blocked it
// for ever), and one that does not open makes it open NAME.mtl beside the OBJ instead. Its name is the rest of the
// line after the blanks (and line ends: assimp skips those too) that follow the keyword. assimp parses the library
// too, so it is checked as well (within the mesh file size limit).
void check_obj_file(std::string_view text, const std::filesystem::path& folder, const MeshLimits& limits) {
  bool vertex_seen = false;
  std::size_t line_number = 1;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string_view line = text.substr(at, end - at);
    const char keyword = line.empty() ? '\0' : line[0];  // assimp goes by the first character: a blank is none
    if (keyword == 'v' && line.size() > 1 && (line[1] == ' ' || line[1] == '\t')) vertex_seen = true;
    if (!vertex_seen && (keyword == 'f' || keyword == 'p' || keyword == 'l')) {
      throw InputError(
          "is an OBJ file with a face, point or line element before its first vertex (expected 'v x y z' "
          "lines before the elements that name them)");
    }
    if (line.rfind("mtllib", 0) == 0 && line.size() > 6 && std::isspace(static_cast<unsigned char>(line[6]))) {
      std::size_t name = at + 6;
      while (name < text.size() && std::isspace(static_cast<unsigned char>(text[name]))) ++name;
      const std::size_t name_end = std::min(text.find_first_of(std::string_view("\r\n\f\0", 4), name), text.size());
      const std::string_view library = text.substr(name, name_end - name);
      const std::string where = "is an OBJ file whose mtllib on line " + std::to_string(line_number);
      check_referenced_file(library, folder, where);
      const std::filesystem::path library_file = folder / std::string(library);
      std::error_code ec;
      const std::uintmax_t bytes = std::filesystem::file_size(library_file, ec);
      if (ec || bytes > limits.max_file_bytes) {
        throw InputError(where + " names " + softbody::one_line(library_file.string()) + ", which has " +
                         (ec ? "an unknown number of" : std::to_string(bytes)) + " bytes, more than the limit of " +
                         std::to_string(limits.max_file_bytes) + " (raise it with the scene key limits.max_file_mb)");
      }
      check_material_library(head_of(library_file, bytes),
                             where + " names " + softbody::one_line(library_file.string()) + ", which");
    }
    at = end + 1;
    ++line_number;
  }
}

// What must hold before assimp opens the file (its readers trust sizes and counts that headers announce).
// Returns the bytes assimp must read instead of the file, where the file alone would be misread (empty: the file).
std::string check_before_reading(const std::filesystem::path& file, const MeshLimits& limits) {
  if (const std::string words = softbody::non_regular_file_words(file); !words.empty()) {
    throw InputError(words + " (expected a regular mesh file)");
  }
  check_format_is_accepted(file);
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
  if (ec) throw InputError("cannot be read (" + ec.message() + ")");
  if (bytes > limits.max_file_bytes) {
    throw InputError("has " + std::to_string(bytes) + " bytes, more than the limit of " +
                     std::to_string(limits.max_file_bytes) + " (raise it with the scene key limits.max_file_mb)");
  }
  constexpr std::uintmax_t kHeadBytes = 64 << 10;  // enough for any PLY or OFF header this loader accepts
  const std::string head = head_of(file, std::min(bytes, kHeadBytes));
  // By content or by name: assimp picks its reader by either (and loops on a .ply that has no PLY header).
  const std::string extension = lower_case_extension(file);
  const std::filesystem::path folder = file.parent_path();
  std::string bytes_for_assimp;
  if (looks_like_ply(head) || extension == ".ply") {
    std::string whole = head_of(file, bytes);
    // assimp misreads triangle strips: it is given the file with faces instead (whose header is checked)
    std::string faces = faces_from_strips(whole, limits.max_triangles);
    const bool strips = !faces.empty();
    if (strips) whole = std::move(faces);
    if (const std::size_t at = check_ply_header(whole, whole.size(), limits); at != std::string::npos) {
      whole.insert(at, 1, '\n');  // the line feed assimp drops (see check_ply_header)
      bytes_for_assimp = std::move(whole);
    } else if (strips) {
      bytes_for_assimp = std::move(whole);
    }
  }
  if (looks_like_off(head) || extension == ".off") {
    check_off_header(head, bytes, limits);
    check_off_face_indices(head_of(file, bytes));
  }
  if (head.rfind("glTF", 0) == 0 || extension == ".glb") {
    check_glb_header(head, bytes);
    constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON" read as a little-endian uint32 (glTF 2.0 §4.4.3)
    if (read_u32_le(head, 16) != kJsonChunk) {
      throw InputError("is a binary glTF 2 (GLB) file whose first chunk is not its JSON chunk");
    }
    // the JSON chunk
    check_gltf_document(head_of(file, std::uintmax_t{20} + read_u32_le(head, 12)).substr(20), folder);
  }
  if (extension == ".gltf") check_gltf_document(head_of(file, bytes), folder);
  if (extension == ".obj") check_obj_file(head_of(file, bytes), folder, limits);
  if (extension == ".fbx" || looks_like_binary_fbx(head) || head.find("FBXHeaderExtension") != std::string::npos) {
    check_fbx_file(head_of(file, bytes));
  }
  return bytes_for_assimp;
}

// (No vertex number in the message: assimp renumbers the vertices of some formats, OBJ among them.)
void check_vertex(const aiVector3D& p) {
  for (int axis = 0; axis < 3; ++axis) {
    const double c = p[static_cast<unsigned>(axis)];
    if (!std::isfinite(c) || std::abs(c) > kMaxMeshCoordinate) {
      char text[160];
      std::snprintf(text, sizeof text, "has a vertex with coordinate %.6g (expected finite coordinates within +-%g)", c,
                    kMaxMeshCoordinate);
      throw InputError(text);
    }
  }
}

// The first UV channel at a triangle's three corners (assimp's floats, exactly; a non-finite one read as 0).
CornerUvs corner_uvs_of(const aiMesh& part, const aiFace& face) {
  CornerUvs uvs{};
  for (unsigned k = 0; k < 3; ++k) {
    const aiVector3D& t = part.mTextureCoords[0][face.mIndices[k]];
    uvs[k] = {std::isfinite(t.x) ? double{t.x} : 0.0, std::isfinite(t.y) ? double{t.y} : 0.0};
  }
  return uvs;
}

// assimp's importer and what it read, shared with the thread that reads (which may outlive the wait for it).
struct AssimpReadState {
  Assimp::Importer importer;
  std::string bytes;  // read instead of the file where not empty
  std::promise<const aiScene*> scene;
};

struct AssimpRead {
  std::shared_ptr<AssimpReadState> state;
  const aiScene* scene = nullptr;  // owned by state->importer; null where assimp could not read the file
};

// assimp reads on a thread of its own while this one waits, calling `while_reading` every 50 ms: a read that takes
// long (an OBJ of 200,000 objects takes minutes: assimp's time grows with the square of the objects) cannot look at
// a stop request itself, so `while_reading` does, and when it throws the reading thread is left to finish or die
// with the process, which exits without waiting for it.
AssimpRead read_with_assimp(const std::filesystem::path& file, std::string bytes_for_assimp,
                            const std::function<void()>& while_reading) {
  auto state = std::make_shared<AssimpReadState>();
  keep_only_accepted_readers(state->importer);
  // Points and lines carry no surface: drop them. Normals and materials are not needed; the first UV channel is
  // kept per corner (assimp splits a vertex on a UV seam into one per side, and the weld joins them again).
  state->importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  state->bytes = std::move(bytes_for_assimp);
  // A glTF buffer's uri is opened by its percent-decoded name, the one check_gltf_document checked.
  const std::string extension = lower_case_extension(file);
  if (extension == ".gltf" || extension == ".glb") state->importer.SetIOHandler(new GltfUriIoSystem(file.string()));
  std::future<const aiScene*> done = state->scene.get_future();
  std::thread reader([state, path = file.string()] {
    // ValidateDataStructure runs first and refuses face indices past a mesh's vertices before the other steps
    // (triangulation reads the vertices a polygon's indices name).
    const unsigned flags = aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_PreTransformVertices |
                           aiProcess_SortByPType;
    try {
      state->scene.set_value(state->bytes.empty() ? state->importer.ReadFile(path, flags)
                                                  : state->importer.ReadFileFromMemory(
                                                        state->bytes.data(), state->bytes.size(), flags, "ply"));
    } catch (...) {
      state->scene.set_exception(std::current_exception());
    }
  });
  while (done.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
    if (!while_reading) continue;
    try {
      while_reading();
    } catch (...) {
      reader.detach();
      throw;
    }
  }
  reader.join();
  return {state, done.get()};
}

}  // namespace

TriMesh import_mesh_file(const std::filesystem::path& file, const MeshLimits& limits,
                         const std::function<void()>& while_reading) {
  const AssimpRead read = read_with_assimp(file, check_before_reading(file, limits), while_reading);
  const aiScene* scene = read.scene;
  const Assimp::Importer& importer = read.state->importer;
  if (scene == nullptr) throw InputError("cannot be read as a mesh: " + std::string(importer.GetErrorString()));
  TriMesh mesh;
  long long vertices = 0, triangles = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    vertices += scene->mMeshes[m]->mNumVertices;
    triangles += scene->mMeshes[m]->mNumFaces;
  }
  if (vertices > limits.max_vertices) {
    throw InputError("has " + std::to_string(vertices) + " vertices, more than the limit of " +
                     std::to_string(limits.max_vertices) + " (raise it with the scene key limits.max_vertices)");
  }
  if (triangles > limits.max_triangles) {
    throw InputError("has " + std::to_string(triangles) + " triangles, more than the limit of " +
                     std::to_string(limits.max_triangles) + " (raise it with the scene key limits.max_triangles)");
  }
  // UVs only where every mesh of the file has them (a mix would leave triangles without).
  bool uvs = true;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) uvs = uvs && scene->mMeshes[m]->HasTextureCoords(0);
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    const int base = static_cast<int>(mesh.vertices.size());
    for (unsigned v = 0; v < part->mNumVertices; ++v) {
      check_vertex(part->mVertices[v]);
      const aiVector3D& p = part->mVertices[v];
      mesh.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (unsigned k = 0; k < 3; ++k) {
        // assimp's readers pass indices through unchecked (a negative text index arrives as a huge one).
        if (face.mIndices[k] >= part->mNumVertices) {
          throw InputError("has a face whose vertex index " + std::to_string(static_cast<int>(face.mIndices[k])) +
                           " is outside the " + std::to_string(part->mNumVertices) + " vertices of its mesh");
        }
      }
      mesh.triangles.push_back({base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                                base + static_cast<int>(face.mIndices[2])});
      if (uvs) mesh.corner_uvs.push_back(corner_uvs_of(*part, face));
    }
  }
  if (mesh.triangles.empty()) throw InputError("holds no triangles (only points or lines?)");
  return mesh;
}

}  // namespace mesh
