// The CPU reference patch sampler (SPEC 3, Sec. 4): per contact, both surfaces' geometry inside
// the viewing volume is rasterised orthographically along n into R x R pixels (depth clip
// |z| <= (|phi| + 0.01 w) / 2 around the contact point, back faces discarded), each fragment's
// meso normal (normal map through the interpolated tangent frame) becomes a ploughing vector
// (friction/fragment_model.hpp), the pixels covered by both surfaces form P, and the
// per-direction means over P enter Eq. 7 with mu0 and the bodies' gains. No GPU needed; the
// OpenGL sampler gives the same numbers. docs/samplers.md describes each step.
//
// Surfaces: a contact's shape_a / shape_b (all shapes of the body when -1). k_A, k_B are the
// gains of those shapes' surfaces (of the first shape when -1); gain masks multiply each
// fragment. Contacts are sampled on the world's threads; scratch buffers (one set per thread)
// and mesh BVHs (one for all threads) are kept between calls.
// Registered as "cpu" in the scene's friction provider registry.
#pragma once

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "asperity/contact_area/mechanical.hpp"
#include "asperity/math/simd_copy.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "asperity/sampler/patch_sampler.hpp"

namespace asperity {

namespace patch {
class MeshCache;
class PatchReuse;
class HeightCache;
}  // namespace patch

// Which friction model the sampler evaluates: the paper's (Eq. 7 with mu0) or the real area
// of contact (SPEC 13, docs/contact-area.md).
enum class FrictionModel { Paper, ContactArea };
inline constexpr std::pair<const char*, FrictionModel> kFrictionModelNames[] = {
    {"paper", FrictionModel::Paper}, {"contact_area", FrictionModel::ContactArea}};

// What the contact-area model needs beyond FrictionSettings.
struct ContactAreaOptions {
  FrictionModel model = FrictionModel::Paper;
  // The world's step (s): the load W of a contact is its previous normal impulse over it.
  double dt = 0.01;
  // Each surface's mechanical values by (body index, shape index); shape index -1 stands for
  // every shape of the body. A contact on a surface without any is an error under the model.
  std::map<std::pair<int, int>, Mechanical> mechanical;
  // Per pair of surfaces (a scene's "pairs"): each surface's class by (body index, shape
  // index) as `mechanical` is keyed (shape -1: every shape of the body), and the model of a
  // pair of classes, keyed (smaller class, larger class). A contact between two surfaces whose
  // classes form a listed pair uses that pair's model; any other contact uses `model`. A
  // contact's surface is its first shape's, as for `mechanical`.
  std::map<std::pair<int, int>, int> surface_class;
  std::map<std::pair<int, int>, FrictionModel> pair_model;

  // The model of a contact between surface (body_a, shape_a) and surface (body_b, shape_b).
  FrictionModel modelFor(int body_a, int shape_a, int body_b, int shape_b) const;
  // Whether any contact may use the contact-area model.
  bool anyContactArea() const;
};

struct CpuSamplerOptions {
  // Which compiled copy of the rasterising, shading and summing loops runs (the same bits
  // either way; tests compare them).
  SimdCopy simd = SimdCopy::Auto;
  ContactAreaOptions contact_area;
};

class CpuPatchSampler : public FrictionProvider {
 public:
  explicit CpuPatchSampler(const CpuSamplerOptions& options = {});
  ~CpuPatchSampler() override;

  std::string name() const override { return "cpu"; }
  // Throws asperity::Error for bad settings (validate(FrictionSettings)), a contact naming a body
  // or shape that does not exist, or a surface with a bad texture_size.
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override;
  // Contacts are sampled in parallel on `pool`, each with its own thread's scratch.
  void setThreadPool(const ThreadPool* pool) override { pool_ = pool; }
  // The contact-area model reads each contact's load (any pair that uses it); the paper's
  // model does not.
  bool readsNormalLoads() const override { return options_.contact_area.anyContactArea(); }
  // Patch and averaging times summed over the threads (CPU time, not wall time).
  double lastPatchTimeMs() const override { return patch_ms_; }
  double lastAveragingTimeMs() const override { return averaging_ms_; }
  int lastReusedCount() const override { return reused_count_; }
  void forgetHistory() override;
  void saveHistory(StateWriter& out) const override;
  void loadHistory(StateReader& in) override;

  // One contact, optionally with its per-pixel images. Same numbers as computeCoefficients.
  void sampleContact(std::span<const Body> bodies, Contact& contact,
                     const FrictionSettings& settings, PatchImages* images = nullptr);

 private:
  struct State;
  void sampleOnPool(std::span<const Body> bodies, std::span<Contact> contacts,
                    const FrictionSettings& settings);

  CpuSamplerOptions options_;
  std::unique_ptr<patch::MeshCache> meshes_;           // shape meshes and BVHs, shared
  std::unique_ptr<State> state_;                       // the calling thread's scratch
  std::vector<std::unique_ptr<State>> worker_states_;  // one per pool thread
  std::unique_ptr<patch::PatchReuse> reuse_;           // earlier samples (patch coherence)
  std::unique_ptr<patch::HeightCache> heights_;        // contact-area model: surface heights
  std::vector<uint8_t> reused_;                        // this call's reuse decisions
  const ThreadPool* pool_ = nullptr;
  double patch_ms_ = 0.0;
  double averaging_ms_ = 0.0;
  int reused_count_ = 0;
};

}  // namespace asperity
