// Asperity's friction as a layer of another engine (MuJoCo, ODE, Bullet, or your own): the
// engine registers each of its objects' surfaces once, hands over each step's contacts in its
// own terms, and gets back for every contact the frame (t, b), mu_d in N directions (SPEC 1,
// 3) and the box bounds (+t, +b, -t, -b) of SPEC 4. The same frame modes, friction providers
// (cpu, cone, constant; gl through a FrictionProviders table that has it), patch reuse and
// threads as a World, with no World: stages 3 and 4 of a step over the engine's contacts
// (docs/engines.md). Deterministic for any thread count; no process-wide state.
//
// Conventions (SPEC 1, asperity/collision/contact.hpp): object A first, the normal points from
// B toward A, depth >= 0 is the penetration; mu_d bounds the friction force on A along d.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "asperity/collision/contact.hpp"
#include "asperity/diagnostics.hpp"
#include "asperity/dynamics/body.hpp"
#include "asperity/frames/contact_frames.hpp"
#include "asperity/friction/limit_surfaces/box_limit.hpp"
#include "asperity/sampler/friction_provider.hpp"

namespace asperity {

class FrictionProviders;
class ThreadPool;

// An engine object's index in a ContactFriction, in the order addObject registered them.
using ObjectId = uint32_t;
inline constexpr ObjectId kNoObject = 0xffffffffu;

struct ContactFrictionSettings {
  FrictionSettings friction;  // N, mu0, mu_max, patch width w and size R, reuse
  // A name of `providers` (cpu, cone, constant, gl); the default is a World's and a scene's.
  std::string provider = kDefaultFrictionProvider;
  // Which friction model each contact uses (a model other than the paper's needs a patch
  // sampler; the contact-area model reads EngineContact::normal_force and each surface's
  // mechanical values). dt is ignored: the engine gives forces.
  FrictionModelSettings models;
  FrameSettings frame;  // SPEC 5; Auto uses the objects' velocities
  int threads = 1;      // 0 = every core, 1 = the calling thread (as WorldSettings)
};

// One engine object, registered once: its surfaces mapped on its shapes, in its own frame
// (the frame whose pose the engine reports; shape transforms relative to it).
struct ObjectDesc {
  std::string name;
  std::vector<Shape> shapes;       // surfaces resolved (resolveSurfaces); planes, boxes, meshes...
  Vec3 frame_axis = Vec3::Zero();  // frame mode Body: t follows this object-local axis
};

// Where an object is this step, in the engine's world frame.
struct ObjectState {
  Transform pose;
  Vec3 linear_velocity = Vec3::Zero();   // m/s, of the frame's origin
  Vec3 angular_velocity = Vec3::Zero();  // rad/s, world frame
};

// One contact as the engine found it.
struct EngineContact {
  ObjectId object_a = kNoObject;
  ObjectId object_b = kNoObject;
  int shape_a = 0;  // index into the object's shapes
  int shape_b = 0;
  int feature_a = -1;  // triangle of a mesh shape, face of a box, when the engine knows it
  int feature_b = -1;
  Vec3 point = Vec3::Zero();    // world, between the two surfaces
  Vec3 normal = Vec3::UnitZ();  // unit, from B toward A
  double depth = 0.0;           // penetration (m), >= 0
  // Identity that persists while the contact does (matches patch samples across steps, and
  // remembers the sense it slid); 0 = none.
  uint64_t key = 0;
  // The normal force the engine's solver last gave this contact (N, >= 0), which the
  // contact-area model's real area depends on; 0: unknown (a new contact), taken as light.
  double normal_force = 0.0;
};

// What a contact gets back.
struct ContactFrictionResult {
  Vec3 t = Vec3::UnitX();  // contact frame, (t, b, n) right-handed, b = n x t
  Vec3 b = Vec3::UnitY();
  DirectionalMu mu;  // mu_d along d_k = cos(2 pi k/N) t + sin(2 pi k/N) b
  BoxLimit bounds;   // +t, +b, -t, -b of mu (SPEC 4, box)
  // For an engine whose friction cone is symmetric (MuJoCo, ODE; SPEC 11): per axis, the
  // coefficient of the sense A slides in relative to B (friction on A opposes it), else the
  // sense it slid last while this key persisted, else the larger of the two.
  double symmetric_t = 0.0;
  double symmetric_b = 0.0;
  Vec3 sliding = Vec3::Zero();  // A's velocity relative to B at the point, in the contact plane
  int covered_pixels = 0;       // |P| of Eq. 8 (patch samplers)
  bool fallback = false;        // P was empty: mu = mu0
};

class ContactFriction {
 public:
  // Throws asperity::Error for bad settings or a provider name `providers` lacks (the table
  // defaults to FrictionProviders::builtIn()).
  explicit ContactFriction(ContactFrictionSettings settings = {});
  ContactFriction(ContactFrictionSettings settings, const FrictionProviders& providers);
  ~ContactFriction();
  ContactFriction(const ContactFriction&) = delete;
  ContactFriction& operator=(const ContactFriction&) = delete;

  // Registers an object; throws asperity::Error naming it for an empty or repeated name, a
  // non-finite shape transform, or a surface that names a normal map it has not resolved.
  ObjectId addObject(const ObjectDesc& desc);
  // The object of that name, or kNoObject.
  ObjectId findObject(std::string_view name) const;
  size_t objectCount() const;

  // Where object `id` is this step. Throws asperity::Error for an unknown id or a non-finite
  // pose or velocity.
  void setState(ObjectId id, const ObjectState& state);

  // Frames, coefficients and bounds of this step's contacts, in their order; valid until the
  // next call. Throws asperity::Error naming the contact for an unknown object or shape, a
  // normal that is not unit or a negative or non-finite depth.
  std::span<const ContactFrictionResult> compute(std::span<const EngineContact> contacts);

  // Forgets kept patch samples and remembered senses (after teleporting objects).
  void forgetHistory();
  // Warnings found while surfaces were resolved for it (the C face resolves them here).
  Diagnostics& diagnostics();
  const ContactFrictionSettings& settings() const;
  // The provider's name and its times in the last compute (ms).
  std::string providerName() const;
  double lastComputeMs() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The coefficient an engine with a symmetric cone should use along one axis: `velocity` is A's
// velocity relative to B along +axis, `last_sense` the sign it last slid with (0: unknown).
// mu_pos / mu_neg bound the friction on A along +axis / -axis (SPEC 1).
double symmetricCoefficient(double mu_pos, double mu_neg, double velocity, int last_sense,
                            double sliding_speed);

}  // namespace asperity
