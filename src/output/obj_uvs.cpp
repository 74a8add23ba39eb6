// OBJ "vt" lines and "f v/vt" faces for per-corner UVs.
#include "output/obj_uvs.hpp"

#include <cstdio>
#include <map>
#include <utility>

namespace output {

std::vector<std::array<int, 3>> append_obj_uvs(std::string& text, std::span<const softbody::CornerUvs> corner_uvs,
                                               int& count) {
  std::map<std::pair<double, double>, int> index_of;  // ordered by value: the same file for the same UVs
  std::vector<std::array<int, 3>> corners(corner_uvs.size());
  char line[96];
  for (std::size_t f = 0; f < corner_uvs.size(); ++f) {
    for (std::size_t k = 0; k < 3; ++k) {
      const softbody::Uv& uv = corner_uvs[f][k];
      const auto [it, fresh] = index_of.emplace(std::make_pair(uv[0], uv[1]), static_cast<int>(index_of.size()));
      if (fresh) {
        std::snprintf(line, sizeof line, "vt %.9g %.9g\n", uv[0], uv[1]);
        text += line;
      }
      corners[f][k] = it->second;
    }
  }
  count += static_cast<int>(index_of.size());
  return corners;
}

void append_obj_face(std::string& text, const softbody::Triangle& face, int first_vertex, const std::array<int, 3>* uv,
                     int first_uv) {
  char line[128];
  if (uv == nullptr) {
    std::snprintf(line, sizeof line, "f %d %d %d\n", face[0] + first_vertex, face[1] + first_vertex,
                  face[2] + first_vertex);
  } else {
    std::snprintf(line, sizeof line, "f %d/%d %d/%d %d/%d\n", face[0] + first_vertex, (*uv)[0] + first_uv,
                  face[1] + first_vertex, (*uv)[1] + first_uv, face[2] + first_vertex, (*uv)[2] + first_uv);
  }
  text += line;
}

}  // namespace output
