# Writes a C++ file holding the text of every shader in SHADERS (a ;-list of paths) as raw string
# literals, so that the program finds its shaders wherever it runs. Run at build time:
#   cmake -DOUTPUT=embedded_shaders.cpp -DSHADERS="a.vert;b.frag" -P embed_shaders.cmake
set(entries "")
foreach(shader IN LISTS SHADERS)
  get_filename_component(name "${shader}" NAME)
  file(READ "${shader}" text)
  string(FIND "${text}" ")glsl\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${shader} contains the raw-string terminator )glsl\"")
  endif()
  string(APPEND entries "    {\"${name}\", R\"glsl(${text})glsl\"},\n")
endforeach()
list(LENGTH SHADERS count)
file(WRITE "${OUTPUT}.new"
"// Generated from shaders/ by cmake/embed_shaders.cmake at build time: edit the shader files instead.
#include \"render/shaders.hpp\"

namespace render {

const EmbeddedShader kEmbeddedShaders[] = {
${entries}};
const std::size_t kEmbeddedShaderCount = ${count};

}  // namespace render
")
# Only touch the output when it changed, so that an unchanged shader set recompiles nothing.
file(COPY_FILE "${OUTPUT}.new" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.new")
