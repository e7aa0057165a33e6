// Headless OpenGL plumbing: the EGL context, shader errors, RAII handles (src/gl).
#include "asperity/gl/context.hpp"

#include <gtest/gtest.h>

#include <string>

#include "asperity/error.hpp"
#include "gl/objects.hpp"
#include "gl/shader.hpp"
#include "render_test_support.hpp"

namespace asperity {
namespace {

TEST(GlContext, CreatesACoreContextOfAtLeast43) {
  gl::GlContext& context = test::sharedContext();
  EXPECT_TRUE(context.isCurrent());
  EXPECT_FALSE(context.renderer().empty());
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  EXPECT_GE(major * 10 + minor, 43) << context.version();
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_TRUE(context.platform() == "surfaceless" || context.platform() == "device" ||
              context.platform() == "default");
}

TEST(GlContext, ASecondContextCanBeMadeCurrentAndBack) {
  gl::GlContext& first = test::sharedContext();
  {
    gl::GlContext second;
    EXPECT_TRUE(second.isCurrent());
    first.makeCurrent();
    EXPECT_TRUE(first.isCurrent());
  }
  first.makeCurrent();
  EXPECT_TRUE(first.isCurrent());
}

TEST(GlContext, TooNewAVersionIsAOneLineError) {
  test::sharedContext();
  gl::GlContextOptions options;
  options.major = 9;
  options.minor = 9;
  try {
    gl::GlContext impossible(options);
    FAIL() << "a 9.9 context was created";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("9.9 core context"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  test::sharedContext();
}

TEST(GlContext, DebugHookReceivesErrors) {
  gl::GlContext& context = test::sharedContext();
  int errors = 0;
  context.setDebugHook([&](const gl::DebugMessage& m) {
    if (m.type == GL_DEBUG_TYPE_ERROR) ++errors;
  });
  glBindTexture(GL_TEXTURE_2D, 0);
  glEnable(static_cast<GLenum>(0x7fff));  // invalid enum
  EXPECT_GE(errors, 1);
  while (glGetError() != GL_NO_ERROR) {
  }
  context.setDebugHook({});
}

TEST(Shader, CompileErrorNamesShaderStageAndLog) {
  test::sharedContext();
  try {
    gl::Program p("tests/broken",
                  {{GL_VERTEX_SHADER,
                    "#version 430 core\nvoid main() { gl_Position = vec4(undeclared_name); }\n"}});
    FAIL() << "compiled";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("tests/broken vertex shader: ", 0), 0u) << message;
    EXPECT_NE(message.find("undeclared_name"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

TEST(Shader, LinkErrorNamesProgram) {
  test::sharedContext();
  // A fragment shader calling a function that no stage defines compiles but cannot link, on
  // every driver (an input the vertex shader never writes links on NVIDIA's).
  const char* vs = "#version 430 core\nvoid main() { gl_Position = vec4(0.0); }\n";
  const char* fs = "#version 430 core\nvec4 shade();\nout vec4 o;\nvoid main() { o = shade(); }\n";
  try {
    gl::Program p("tests/unlinked", {{GL_VERTEX_SHADER, vs}, {GL_FRAGMENT_SHADER, fs}});
    FAIL() << "linked";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("tests/unlinked program link: ", 0), 0u) << e.what();
  }
}

TEST(Shader, WorkingProgramSetsUniforms) {
  test::sharedContext();
  gl::Program p(
      "tests/ok",
      {{GL_VERTEX_SHADER,
        "#version 430 core\nuniform float u_x;\nvoid main() { gl_Position = vec4(u_x); }\n"}});
  EXPECT_NE(p.id(), 0u);
  p.set("u_x", 2.5f);
  GLfloat value = 0.0f;
  glGetUniformfv(p.id(), p.location("u_x"), &value);
  EXPECT_EQ(value, 2.5f);
}

TEST(Objects, HandlesOwnNamesAndMove) {
  test::sharedContext();
  gl::Texture a;
  const GLuint name = a.id();
  EXPECT_NE(name, 0u);
  gl::Texture b = std::move(a);
  EXPECT_EQ(b.id(), name);
  EXPECT_EQ(a.id(), 0u);  // NOLINT: moved-from state is defined (empty)
}

TEST(Objects, IncompleteFramebufferIsNamed) {
  test::sharedContext();
  gl::Framebuffer fbo;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  try {
    gl::checkFramebufferComplete("tests/empty");
    FAIL() << "an empty framebuffer was complete";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'tests/empty' is incomplete"), std::string::npos);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace asperity
