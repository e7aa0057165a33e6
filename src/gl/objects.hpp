// Move-only RAII owners of OpenGL object names (buffers, textures, framebuffers, ...). Each
// creates its name in the constructor and deletes it in the destructor; the context that was
// current at creation must be current at destruction.
#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace asperity::gl {

// One owned GL name with its deleter (GenFn/DeleteFn in the glGen*/glDelete* shape).
template <void (*Create)(GLuint*), void (*Destroy)(GLuint)>
class Handle {
 public:
  Handle() { Create(&name_); }
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint id() const { return name_; }
  operator GLuint() const { return name_; }  // NOLINT: pass straight to gl* calls

 private:
  void reset() {
    if (name_ != 0) Destroy(name_);
    name_ = 0;
  }
  GLuint name_ = 0;
};

namespace detail {
void createBuffer(GLuint* n);
void deleteBuffer(GLuint n);
void createVertexArray(GLuint* n);
void deleteVertexArray(GLuint n);
void createTexture(GLuint* n);
void deleteTexture(GLuint n);
void createFramebuffer(GLuint* n);
void deleteFramebuffer(GLuint n);
void createRenderbuffer(GLuint* n);
void deleteRenderbuffer(GLuint n);
}  // namespace detail

using Buffer = Handle<detail::createBuffer, detail::deleteBuffer>;
using VertexArray = Handle<detail::createVertexArray, detail::deleteVertexArray>;
using Texture = Handle<detail::createTexture, detail::deleteTexture>;
using Framebuffer = Handle<detail::createFramebuffer, detail::deleteFramebuffer>;
using Renderbuffer = Handle<detail::createRenderbuffer, detail::deleteRenderbuffer>;

// Throws asperity::Error naming `what` unless the bound draw framebuffer is complete.
void checkFramebufferComplete(const char* what);

// Throws asperity::Error naming `where` and the GL error code if glGetError reports one.
void checkGlError(const char* where);

}  // namespace asperity::gl
