// The OpenGL patch sampler (SPEC 3, Sec. 4 of the paper): both surfaces of every contact are
// rendered into R x R tiles of an atlas frame buffer (one orthographic view per contact, the
// tile as viewport), the fragment shader evaluates Eq. 5 for the N directions into N / 4 RGBA
// targets at once (plus a coverage target), a compute shader sums each contact's two tiles over
// the pixels both cover (Eq. 8), and the sums come back through a storage buffer and a fence
// while the next pass renders; the CPU divides and combines them as the CPU sampler does (Eq.
// 7). More contacts than the atlas holds take further passes; more directions than the frame
// buffer's draw buffers take further sub-passes.
//
// Geometry is the CPU sampler's (box faces and planes exact, meshes via their BVH) except that
// spheres, capsules and cylinders are tessellated (1024 x 128) instead of ray-cast.
// Normal maps are uploaded once per NormalMap (RGB32F, bilinear, repeat) and cached.
// Packing: RGBA8 with scale mu_max as the paper (coefficients above mu_max saturate, steps of
// mu_max / 255), or RGBA32F targets (float_targets).
#pragma once

#include <memory>

#include "asperity/sampler/friction_provider.hpp"
#include "asperity/sampler/patch_sampler.hpp"

namespace asperity {

struct GlSamplerOptions {
  int atlas_size = 1024;       // frame buffer side (pixels)
  bool float_targets = false;  // RGBA32F instead of RGBA8
  // Render with the caller's current context (e.g. the viewer's); the sampler restores the
  // frame buffer, program, vertex array, viewport and depth/cull/blend state it changes.
  // Otherwise it owns a headless context and makes it current in each call (leaving it so).
  bool use_current_context = false;
};

class GlPatchSampler : public PatchSampler {
 public:
  // Creates a headless context (gl/context.hpp) unless use_current_context. Throws
  // asperity::Error when no OpenGL 4.3 context is available or the options are bad.
  explicit GlPatchSampler(const GlSamplerOptions& options = {});
  ~GlPatchSampler() override;

  std::string name() const override { return "gl"; }
  // Throws asperity::Error for bad settings (validate(FrictionSettings), N a multiple of 4), bad
  // contacts or surfaces, or a GL failure.
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override;
  // Start renders and sums every pass and queues the last read-backs; finish waits for them and
  // divides. A call started again before it finished drops the unfinished one.
  void startCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                         const FrictionSettings& settings) override;
  void finishCoefficients() override;
  bool runsAsynchronously() const override { return true; }
  // The triangles are collected and the read-back sums finished on `pool`'s threads (the same
  // bits on any count); GL calls stay on the calling thread.
  void setThreadPool(const ThreadPool* pool) override;
  // Patch times as the CPU sampler's, passes (atlas fills) and the contacts that kept their
  // sample (PatchSampler): those are not rendered.
  ProviderStats lastStats() const override;
  // GL_RENDERER of the context in use, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// addGlPatchSampler, which offers this sampler to scenes as "gl", is in the scene layer:
// asperity/scene/gl_sampler_provider.hpp.

}  // namespace asperity
