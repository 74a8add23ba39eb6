// The GLSL sources in shaders/, compiled into the program (cmake/embed_shaders.cmake), and the linked
// programs built from them.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "render/gl.hpp"

namespace render {

struct EmbeddedShader {
  const char* name;    // file name in shaders/, e.g. "body.frag"
  const char* source;  // its text
};
extern const EmbeddedShader kEmbeddedShaders[];
extern const std::size_t kEmbeddedShaderCount;

// The text of shaders/<name>. Throws std::logic_error when no such shader was embedded.
std::string_view shader_source(std::string_view name);

// A linked GLSL program. Each stage is the concatenation of the named shader files after a
// "#version 330 core" line (so shared code such as lighting.glsl can be prepended to a stage).
class ShaderProgram {
 public:
  ShaderProgram(std::initializer_list<std::string_view> vertex_files,
                std::initializer_list<std::string_view> fragment_files);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  // Uniform setters for the program in use; a uniform the compiler removed as unused is ignored.
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::mat4& value) const;

 private:
  GLuint program_ = 0;
};

}  // namespace render
