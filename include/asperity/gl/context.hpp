// A headless OpenGL context through EGL (no window, no X server): Mesa's llvmpipe on machines
// without a GPU, the vendor driver (NVIDIA, Mesa) otherwise. The GPU patch sampler, the
// renderer's offscreen path and the tests all use it.
//
// Display selection, first that works: EGL_MESA_platform_surfaceless, then each device of
// EGL_EXT_platform_device, then the default display. The context is made current without a
// surface (EGL_KHR_surfaceless_context) or, failing that, with a 16 x 16 pbuffer.
#pragma once

#include <functional>
#include <string>

namespace asperity::gl {

struct GlContextOptions {
  int major = 4;  // OpenGL core profile version asked for (4.3 at least: debug output, SSBOs)
  int minor = 3;
  bool debug = false;  // a debug context; messages go to the debug hook (or stderr)
};

// One message of KHR_debug / GL 4.3 debug output.
struct DebugMessage {
  unsigned source = 0;
  unsigned type = 0;
  unsigned id = 0;
  unsigned severity = 0;
  std::string text;
};

using DebugHook = std::function<void(const DebugMessage&)>;

class GlContext {
 public:
  // Creates the context and makes it current on the calling thread. Throws asperity::Error
  // (one line, naming what failed: no EGL display, no config, no core context of that version).
  explicit GlContext(const GlContextOptions& options = {});
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes this context current on the calling thread (after another one was).
  void makeCurrent() const;
  bool isCurrent() const;

  // GL_RENDERER, GL_VENDOR and GL_VERSION strings, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer() const;
  std::string vendor() const;
  std::string version() const;
  // Which display path was taken: "surfaceless", "device", or "default".
  const std::string& platform() const { return platform_; }

  // Routes GL debug output of this context to `hook` (empty: back to stderr for errors only).
  // Enables synchronous debug output; works on any 4.3 context, richer on a debug one.
  void setDebugHook(DebugHook hook);

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  void* surface_ = nullptr;
  std::string platform_;
  DebugHook hook_;
};

// Installs a GL debug-output callback on the CURRENT context (any 4.3+ context, e.g. a GLFW
// window's). `hook` must outlive the context's use; null restores the default (errors to stderr).
void installDebugHook(const DebugHook* hook);

}  // namespace asperity::gl
