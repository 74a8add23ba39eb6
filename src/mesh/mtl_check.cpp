// The statements an MTL file may hold before its first material: none (blank lines and comments only).
#include "mesh/mtl_check.hpp"

#include <algorithm>
#include <string>

#include "core/errors.hpp"
#include "core/one_line.hpp"

namespace mesh {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// "newmtl" alone or followed by a blank (and the material's name).
bool starts_a_material(std::string_view statement) {
  return statement.rfind("newmtl", 0) == 0 && (statement.size() == 6 || is_blank(statement[6]));
}

}  // namespace

void check_material_library(std::string_view text, const std::string& where) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.remove_prefix(3);
  constexpr std::string_view kLineEnds("\r\n\f\0", 4);
  std::size_t line_number = 1;
  for (std::size_t at = 0; at < text.size(); ++line_number) {
    const std::size_t end = std::min(text.find_first_of(kLineEnds, at), text.size());
    std::string_view statement = text.substr(at, end - at);
    while (!statement.empty() && is_blank(statement.front())) statement.remove_prefix(1);
    if (starts_a_material(statement)) return;
    if (!statement.empty() && statement.front() != '#') {
      const std::string_view keyword = statement.substr(0, statement.find_first_of(" \t"));
      throw softbody::InputError(where + " has a statement \"" + softbody::one_line(keyword.substr(0, 40)) +
                                 "\" on line " + std::to_string(line_number) +
                                 " before its first material (expected comments only before the first 'newmtl "
                                 "NAME'; softbody does not use materials: the mtllib line may go)");
    }
    at = end + 1;
  }
}

}  // namespace mesh
