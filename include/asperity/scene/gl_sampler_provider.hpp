// The OpenGL patch sampler as a named friction provider: "gl" in a scene's table of providers
// (friction_providers.hpp). The registration lives here, in the scene layer, so that the
// sampler's own header knows nothing of scenes. Header-only: a program that calls it links
// asperity::gl, and the core library still never links OpenGL.
#pragma once

#include <memory>

#include "asperity/sampler/gl_patch_sampler.hpp"
#include "asperity/scene/friction_providers.hpp"

namespace asperity {

// Adds "gl" (a GlPatchSampler with these options) to a table of friction providers, e.g. the
// one given to instantiate().
inline void addGlPatchSampler(FrictionProviders& providers, const GlSamplerOptions& options = {}) {
  providers.add("gl", [options] { return std::make_unique<GlPatchSampler>(options); });
}

}  // namespace asperity
