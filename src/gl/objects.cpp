// Name creation and deletion for the RAII handles, and completeness checks.
#include "gl/objects.hpp"

#include <cstdio>
#include <string>

#include "asperity/error.hpp"

namespace asperity::gl {
namespace detail {

void createBuffer(GLuint* n) {
  glGenBuffers(1, n);
}
void deleteBuffer(GLuint n) {
  glDeleteBuffers(1, &n);
}
void createVertexArray(GLuint* n) {
  glGenVertexArrays(1, n);
}
void deleteVertexArray(GLuint n) {
  glDeleteVertexArrays(1, &n);
}
void createTexture(GLuint* n) {
  glGenTextures(1, n);
}
void deleteTexture(GLuint n) {
  glDeleteTextures(1, &n);
}
void createFramebuffer(GLuint* n) {
  glGenFramebuffers(1, n);
}
void deleteFramebuffer(GLuint n) {
  glDeleteFramebuffers(1, &n);
}
void createRenderbuffer(GLuint* n) {
  glGenRenderbuffers(1, n);
}
void deleteRenderbuffer(GLuint n) {
  glDeleteRenderbuffers(1, &n);
}

}  // namespace detail

namespace {
std::string hex(unsigned value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04x", value);
  return buffer;
}
}  // namespace

void checkFramebufferComplete(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error(std::string("OpenGL: framebuffer '") + what + "' is incomplete (status " +
                hex(status) + ")");
}

void checkGlError(const char* where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
    throw Error(std::string("OpenGL: error ") + hex(error) + " in " + where);
}

}  // namespace asperity::gl
