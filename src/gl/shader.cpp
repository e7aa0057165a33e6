// Shader compilation and linking with readable one-line errors.
#include "gl/shader.hpp"

#include <algorithm>
#include <utility>

#include "asperity/error.hpp"

namespace asperity::gl {
namespace {

const char* stageName(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER:
      return "vertex";
    case GL_FRAGMENT_SHADER:
      return "fragment";
    case GL_GEOMETRY_SHADER:
      return "geometry";
    case GL_COMPUTE_SHADER:
      return "compute";
    case GL_TESS_CONTROL_SHADER:
      return "tessellation control";
    case GL_TESS_EVALUATION_SHADER:
      return "tessellation evaluation";
    default:
      return "unknown";
  }
}

// Info logs span lines; errors are one line.
std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && (text.back() == ' ' || text.back() == '\0')) text.pop_back();
  return text;
}

}  // namespace

GLuint compileShader(const std::string& name, const ShaderSource& source) {
  const GLuint shader = glCreateShader(source.stage);
  const GLchar* text = source.source.data();
  const GLint length = static_cast<GLint>(source.source.size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    // Read the log before deleting the shader.
    GLint log_length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &log_length);
    std::string log(static_cast<size_t>(std::max(log_length, 1)), '\0');
    glGetShaderInfoLog(shader, log_length, nullptr, log.data());
    glDeleteShader(shader);
    throw Error(name + " " + stageName(source.stage) + " shader: " + oneLine(log));
  }
  return shader;
}

GLuint linkProgram(const std::string& name, const std::vector<GLuint>& shaders) {
  const GLuint program = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(program, s);
  glLinkProgram(program);
  for (GLuint s : shaders) glDetachShader(program, s);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint log_length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &log_length);
    std::string log(static_cast<size_t>(std::max(log_length, 1)), '\0');
    glGetProgramInfoLog(program, log_length, nullptr, log.data());
    glDeleteProgram(program);
    throw Error(name + " program link: " + oneLine(log));
  }
  return program;
}

Program::Program(std::string name, const std::vector<ShaderSource>& stages)
    : name_(std::move(name)) {
  // Compile every stage, deleting the ones already built if a later one fails.
  std::vector<GLuint> shaders;
  try {
    for (const ShaderSource& s : stages) shaders.push_back(compileShader(name_, s));
    id_ = linkProgram(name_, shaders);
  } catch (...) {
    for (GLuint s : shaders) glDeleteShader(s);
    throw;
  }
  for (GLuint s : shaders) glDeleteShader(s);
}

Program::~Program() {
  if (id_ != 0) glDeleteProgram(id_);
}

Program::Program(Program&& other) noexcept
    : name_(std::move(other.name_)), id_(std::exchange(other.id_, 0)) {}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteProgram(id_);
    name_ = std::move(other.name_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

void Program::set(const char* uniform, int value) const {
  glProgramUniform1i(id_, location(uniform), value);
}
void Program::set(const char* uniform, float value) const {
  glProgramUniform1f(id_, location(uniform), value);
}
void Program::set(const char* uniform, const Vec3f& value) const {
  glProgramUniform3fv(id_, location(uniform), 1, value.data());
}
void Program::set(const char* uniform, const Eigen::Vector4f& value) const {
  glProgramUniform4fv(id_, location(uniform), 1, value.data());
}
// Eigen is column-major like GLSL: no transpose.
void Program::set(const char* uniform, const Eigen::Matrix3f& value) const {
  glProgramUniformMatrix3fv(id_, location(uniform), 1, GL_FALSE, value.data());
}
void Program::set(const char* uniform, const Eigen::Matrix4f& value) const {
  glProgramUniformMatrix4fv(id_, location(uniform), 1, GL_FALSE, value.data());
}

}  // namespace asperity::gl
