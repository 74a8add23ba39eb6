// Owners of OpenGL object names: each deletes its object when it goes out of scope, and moves.
#pragma once

#include <utility>

#include "render/gl.hpp"

namespace render {

// One GL object name with the functions that make and delete it (glGen*/glDelete*-shaped).
template <void (*Create)(GLsizei, GLuint*), void (*Delete)(GLsizei, const GLuint*)>
class GlName {
 public:
  GlName() { Create(1, &name_); }
  ~GlName() {
    if (name_ != 0) Delete(1, &name_);
  }
  GlName(GlName&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  GlName& operator=(GlName&& other) noexcept {
    std::swap(name_, other.name_);
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;

  GLuint get() const { return name_; }

 private:
  GLuint name_ = 0;
};

// The glGen* functions are declared as GLAPI functions; these wrappers give them a plain signature.
inline void gen_buffers(GLsizei n, GLuint* names) { glGenBuffers(n, names); }
inline void delete_buffers(GLsizei n, const GLuint* names) { glDeleteBuffers(n, names); }
inline void gen_vertex_arrays(GLsizei n, GLuint* names) { glGenVertexArrays(n, names); }
inline void delete_vertex_arrays(GLsizei n, const GLuint* names) { glDeleteVertexArrays(n, names); }
inline void gen_textures(GLsizei n, GLuint* names) { glGenTextures(n, names); }
inline void delete_textures(GLsizei n, const GLuint* names) { glDeleteTextures(n, names); }
inline void gen_framebuffers(GLsizei n, GLuint* names) { glGenFramebuffers(n, names); }
inline void delete_framebuffers(GLsizei n, const GLuint* names) { glDeleteFramebuffers(n, names); }
inline void gen_renderbuffers(GLsizei n, GLuint* names) { glGenRenderbuffers(n, names); }
inline void delete_renderbuffers(GLsizei n, const GLuint* names) { glDeleteRenderbuffers(n, names); }

using GlBuffer = GlName<gen_buffers, delete_buffers>;
using GlVertexArray = GlName<gen_vertex_arrays, delete_vertex_arrays>;
using GlTexture = GlName<gen_textures, delete_textures>;
using GlFramebuffer = GlName<gen_framebuffers, delete_framebuffers>;
using GlRenderbuffer = GlName<gen_renderbuffers, delete_renderbuffers>;

}  // namespace render
