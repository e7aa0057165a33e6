// Shader compile/link helpers. Errors are asperity::Error naming the shader and carrying the
// driver's info log (newlines folded so the message stays one line).
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <string_view>
#include <vector>

#include "asperity/math/types.hpp"

namespace asperity::gl {

struct ShaderSource {
  GLenum stage = GL_VERTEX_SHADER;  // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER...
  std::string_view source;          // GLSL including its #version line
};

// A linked program (move-only). Uniform setters look the location up by name and ignore
// uniforms the compiler removed.
class Program {
 public:
  Program() = default;
  // Compiles and links; `name` appears in error messages ("renderer/mesh vertex shader: ...").
  Program(std::string name, const std::vector<ShaderSource>& stages);
  ~Program();
  Program(Program&& other) noexcept;
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  GLuint id() const { return id_; }
  const std::string& name() const { return name_; }
  void use() const { glUseProgram(id_); }

  GLint location(const char* uniform) const { return glGetUniformLocation(id_, uniform); }
  void set(const char* uniform, int value) const;
  void set(const char* uniform, float value) const;
  void set(const char* uniform, const Vec3f& value) const;
  void set(const char* uniform, const Eigen::Vector4f& value) const;
  void set(const char* uniform, const Eigen::Matrix3f& value) const;
  void set(const char* uniform, const Eigen::Matrix4f& value) const;

 private:
  std::string name_;
  GLuint id_ = 0;
};

// Compiles one stage; throws asperity::Error "<name> <stage> shader: <info log>".
GLuint compileShader(const std::string& name, const ShaderSource& source);
// Links compiled stages; throws asperity::Error "<name> program link: <info log>".
GLuint linkProgram(const std::string& name, const std::vector<GLuint>& shaders);

}  // namespace asperity::gl
