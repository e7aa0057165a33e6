// Headless EGL context creation (see include/asperity/gl/context.hpp for the search order).
#include "asperity/gl/context.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "asperity/error.hpp"

namespace asperity::gl {
namespace {

// Text for the last EGL error, for messages.
std::string eglErrorText() {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
  return buffer;
}

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
    const bool start = p == list || p[-1] == ' ';
    const bool end = p[n] == '\0' || p[n] == ' ';
    if (start && end) return true;
  }
  return false;
}

// Tries to initialise a display; returns it or EGL_NO_DISPLAY (terminated on failure).
EGLDisplay tryInitialise(EGLDisplay display) {
  if (display == EGL_NO_DISPLAY) return EGL_NO_DISPLAY;
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor) != EGL_TRUE) return EGL_NO_DISPLAY;
  // Desktop OpenGL must be bindable on it.
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
    eglTerminate(display);
    return EGL_NO_DISPLAY;
  }
  return display;
}

// EGL_EXT_platform_device: the first device whose display initialises.
EGLDisplay tryDevices() {
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") &&
      !epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_base"))
    return EGL_NO_DISPLAY;
  EGLint count = 0;
  if (eglQueryDevicesEXT(0, nullptr, &count) != EGL_TRUE || count <= 0) return EGL_NO_DISPLAY;
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  eglQueryDevicesEXT(count, devices.data(), &count);
  for (EGLint i = 0; i < count; ++i) {
    EGLDisplay d =
        tryInitialise(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
    if (d != EGL_NO_DISPLAY) return d;
  }
  return EGL_NO_DISPLAY;
}

// Picks a display in the documented order and records which path was taken.
EGLDisplay openDisplay(std::string& platform) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (hasExtension(client, "EGL_EXT_platform_base")) {
    if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
      EGLDisplay d = tryInitialise(
          eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
      if (d != EGL_NO_DISPLAY) return platform = "surfaceless", d;
    }
    if (hasExtension(client, "EGL_EXT_platform_device")) {
      EGLDisplay d = tryDevices();
      if (d != EGL_NO_DISPLAY) return platform = "device", d;
    }
  }
  EGLDisplay d = tryInitialise(eglGetDisplay(EGL_DEFAULT_DISPLAY));
  if (d != EGL_NO_DISPLAY) return platform = "default", d;
  throw Error(
      "OpenGL: no EGL display (tried EGL_MESA_platform_surfaceless, EGL_EXT_platform_device and "
      "the default display); install libegl-mesa0 and libgl1-mesa-dri (llvmpipe) or a GPU "
      "driver");
}

// Default debug output: GL errors on stderr, the rest dropped (shader compile errors reach
// callers through the exceptions of gl/shader.hpp instead).
void defaultDebugPrint(const DebugMessage& m) {
  if (m.type == GL_DEBUG_TYPE_ERROR && m.source != GL_DEBUG_SOURCE_SHADER_COMPILER)
    std::fprintf(stderr, "OpenGL error: %s\n", m.text.c_str());
}

void GLAPIENTRY debugCallback(GLenum source, GLenum type, GLuint id, GLenum severity,
                              GLsizei length, const GLchar* message, const void* user) {
  DebugMessage m{
      source, type, id, severity,
      std::string(message, length >= 0 ? static_cast<size_t>(length) : std::strlen(message))};
  const auto* hook = static_cast<const DebugHook*>(user);
  if (hook != nullptr && *hook) {
    (*hook)(m);
  } else {
    defaultDebugPrint(m);
  }
}

}  // namespace

void installDebugHook(const DebugHook* hook) {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(debugCallback, hook);
}

namespace {

// A config that can render desktop OpenGL (pbuffer bit for the fallback surface); on a
// surfaceless display one without that bit will do.
EGLConfig chooseConfig(EGLDisplay display, bool surfaceless, const std::string& platform) {
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE,
                                   EGL_PBUFFER_BIT,
                                   EGL_RENDERABLE_TYPE,
                                   EGL_OPENGL_BIT,
                                   EGL_RED_SIZE,
                                   8,
                                   EGL_GREEN_SIZE,
                                   8,
                                   EGL_BLUE_SIZE,
                                   8,
                                   EGL_ALPHA_SIZE,
                                   8,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint num_configs = 0;
  if (eglChooseConfig(display, config_attribs, &config, 1, &num_configs) == EGL_TRUE &&
      num_configs > 0)
    return config;
  // Surfaceless displays may expose configs without the pbuffer bit.
  const EGLint any[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  if (!surfaceless || eglChooseConfig(display, any, &config, 1, &num_configs) != EGL_TRUE ||
      num_configs == 0) {
    throw Error("OpenGL: no EGL config for desktop OpenGL on the " + platform + " display (" +
                eglErrorText() + ")");
  }
  return config;
}

// A core profile context of the requested version.
EGLContext createCoreContext(EGLDisplay display, EGLConfig config, const GlContextOptions& options,
                             const std::string& platform) {
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                    options.major,
                                    EGL_CONTEXT_MINOR_VERSION,
                                    options.minor,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_CONTEXT_OPENGL_DEBUG,
                                    options.debug ? EGL_TRUE : EGL_FALSE,
                                    EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
  if (context == EGL_NO_CONTEXT) {
    const std::string why = eglErrorText();
    throw Error("OpenGL: cannot create a " + std::to_string(options.major) + "." +
                std::to_string(options.minor) + " core context on the " + platform + " display (" +
                why + ")");
  }
  return context;
}

}  // namespace

GlContext::GlContext(const GlContextOptions& options) {
  EGLDisplay display = openDisplay(platform_);
  display_ = display;
  const bool surfaceless = epoxy_has_egl_extension(display, "EGL_KHR_surfaceless_context");
  EGLConfig config = chooseConfig(display, surfaceless, platform_);
  EGLContext context = createCoreContext(display, config, options, platform_);
  context_ = context;
  // No surface where allowed, else a small pbuffer (rendering goes to framebuffer objects).
  if (!surfaceless) {
    const EGLint pbuffer_attribs[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    surface_ = eglCreatePbufferSurface(display, config, pbuffer_attribs);
    if (surface_ == EGL_NO_SURFACE) {
      const std::string why = eglErrorText();
      eglDestroyContext(display, context);
      throw Error("OpenGL: cannot create a pbuffer surface (" + why + ")");
    }
  }
  makeCurrent();
  if (options.debug) setDebugHook({});
}

GlContext::~GlContext() {
  EGLDisplay display = display_;
  // Release only this context: another one may be current on this thread.
  if (eglGetCurrentContext() == context_)
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface_ != nullptr) eglDestroySurface(display, surface_);
  eglDestroyContext(display, context_);
  // The display stays initialised: EGL displays are shared per process, and terminating one
  // would destroy every other context on it (failure paths above leave it alone for the same
  // reason).
}

void GlContext::makeCurrent() const {
  EGLSurface surface = surface_ != nullptr ? surface_ : EGL_NO_SURFACE;
  if (eglMakeCurrent(display_, surface, surface, context_) != EGL_TRUE)
    throw Error("OpenGL: cannot make the EGL context current (" + eglErrorText() + ")");
}

bool GlContext::isCurrent() const {
  return eglGetCurrentContext() == context_;
}

namespace {
std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s != nullptr ? reinterpret_cast<const char*>(s) : "";
}
}  // namespace

std::string GlContext::renderer() const {
  return glString(GL_RENDERER);
}
std::string GlContext::vendor() const {
  return glString(GL_VENDOR);
}
std::string GlContext::version() const {
  return glString(GL_VERSION);
}

void GlContext::setDebugHook(DebugHook hook) {
  hook_ = std::move(hook);
  installDebugHook(&hook_);
}

}  // namespace asperity::gl
