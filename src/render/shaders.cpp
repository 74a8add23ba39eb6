// Finding embedded shader sources; compiling and linking programs with their logs in the errors.
#include "render/shaders.hpp"

#include <stdexcept>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

namespace render {
namespace {

constexpr const char* kVersionLine = "#version 330 core\n";

std::string join_names(std::initializer_list<std::string_view> files) {
  std::string names;
  for (std::string_view file : files) names += (names.empty() ? "" : "+") + std::string(file);
  return names;
}

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  if (is_program)
    glGetProgramInfoLog(object, length, nullptr, log.data());
  else
    glGetShaderInfoLog(object, length, nullptr, log.data());
  return log.c_str();
}

GLuint compile_stage(GLenum stage, std::initializer_list<std::string_view> files) {
  std::vector<const GLchar*> texts{kVersionLine};
  std::vector<GLint> lengths{static_cast<GLint>(std::string_view(kVersionLine).size())};
  for (std::string_view file : files) {
    const std::string_view text = shader_source(file);
    texts.push_back(text.data());
    lengths.push_back(static_cast<GLint>(text.size()));
  }
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, static_cast<GLsizei>(texts.size()), texts.data(), lengths.data());
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = info_log(shader, false);
    glDeleteShader(shader);
    throw std::runtime_error("shader " + join_names(files) + " does not compile:\n" + log);
  }
  return shader;
}

}  // namespace

std::string_view shader_source(std::string_view name) {
  for (std::size_t i = 0; i < kEmbeddedShaderCount; ++i) {
    if (name == kEmbeddedShaders[i].name) return kEmbeddedShaders[i].source;
  }
  throw std::logic_error("no shader named " + std::string(name) + " was embedded (see CMakeLists.txt)");
}

ShaderProgram::ShaderProgram(std::initializer_list<std::string_view> vertex_files,
                             std::initializer_list<std::string_view> fragment_files) {
  const GLuint vertex = compile_stage(GL_VERTEX_SHADER, vertex_files);
  GLuint fragment = 0;
  try {
    fragment = compile_stage(GL_FRAGMENT_SHADER, fragment_files);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);  // flagged for deletion; freed with the program
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = info_log(program_, true);
    glDeleteProgram(program_);
    throw std::runtime_error("shader program " + join_names(vertex_files) + ", " + join_names(fragment_files) +
                             " does not link:\n" + log);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(program_); }

void ShaderProgram::use() const { glUseProgram(program_); }

void ShaderProgram::set(const char* name, int value) const { glUniform1i(glGetUniformLocation(program_, name), value); }
void ShaderProgram::set(const char* name, float value) const {
  glUniform1f(glGetUniformLocation(program_, name), value);
}
void ShaderProgram::set(const char* name, const glm::vec3& value) const {
  glUniform3fv(glGetUniformLocation(program_, name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat4& value) const {
  glUniformMatrix4fv(glGetUniformLocation(program_, name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace render
