// The CPU reference patch sampler (SPEC 3, Sec. 4): per contact, both surfaces' geometry inside
// the viewing volume is rasterised orthographically along n into R x R pixels (depth clip
// |z| <= (|phi| + 0.01 w) / 2 around the contact point, back faces discarded), each fragment's
// meso normal (normal map through the interpolated tangent frame) becomes a ploughing vector
// (friction/fragment_model.hpp), the pixels covered by both surfaces form P, and the contact's
// friction model (sampler/models/) reduces P's fragments to mu_d. No GPU needed; the OpenGL
// sampler gives the same numbers. docs/samplers.md describes each step.
//
// Surfaces: a contact's shape_a / shape_b (all shapes of the body when -1). k_A, k_B are the
// gains of those shapes' surfaces (of the first shape when -1); gain masks multiply each
// fragment. Contacts are sampled on the world's threads; scratch buffers (one set per thread)
// and mesh BVHs (one for all threads) are kept between calls.
// Registered as "cpu" in the scene's friction provider registry.
#pragma once

#include <memory>
#include <vector>

#include "asperity/math/simd_copy.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "asperity/sampler/patch_sampler.hpp"

namespace asperity {

namespace patch {
class MeshCache;
class HeightCache;
}  // namespace patch

struct CpuSamplerOptions {
  // Which compiled copy of the rasterising, shading and summing loops runs (the same bits
  // either way; tests compare them).
  SimdCopy simd = SimdCopy::Auto;
};

class CpuPatchSampler : public PatchSampler {
 public:
  explicit CpuPatchSampler(const CpuSamplerOptions& options = {});
  ~CpuPatchSampler() override;

  std::string name() const override { return "cpu"; }
  // Throws asperity::Error for bad settings (validate(FrictionSettings)), a contact naming a body
  // or shape that does not exist, a surface with a bad texture_size, or a contact whose model
  // lacks what it reads (the contact-area model's mechanical values).
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override;
  // Contacts are sampled in parallel on `pool`, each with its own thread's scratch.
  void setThreadPool(const ThreadPool* pool) override { pool_ = pool; }

  // One contact, optionally with its per-pixel images. Same numbers as computeCoefficients.
  void sampleContact(std::span<const Body> bodies, Contact& contact,
                     const FrictionSettings& settings, PatchImages* images = nullptr);

 private:
  struct State;
  void prepareHeights(std::span<const Body> bodies, std::span<Contact* const> contacts);
  void sampleOnPool(std::span<const Body> bodies, std::span<Contact> contacts,
                    std::span<Contact* const> to_sample, const FrictionSettings& settings);

  CpuSamplerOptions options_;
  std::unique_ptr<patch::MeshCache> meshes_;           // shape meshes and BVHs, shared
  std::unique_ptr<patch::HeightCache> heights_;        // surface heights, for models that read them
  std::unique_ptr<State> state_;                       // the calling thread's scratch
  std::vector<std::unique_ptr<State>> worker_states_;  // one per pool thread
  const ThreadPool* pool_ = nullptr;
};

}  // namespace asperity
