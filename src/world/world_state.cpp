// A world's state saved and restored bit for bit (World::saveState, docs/checkpoints.md). The
// scene rebuilds what never changes (shapes, masses, joints' frames, settings); the state holds
// what steps change, each stage writing its own persistence.
#include <cstdint>
#include <string>

#include "asperity/error.hpp"
#include "asperity/math/state_stream.hpp"
#include "asperity/world/world.hpp"
#include "collision/collision_detector.hpp"
#include "solver/contact_solver.hpp"

namespace asperity {
namespace {

void putVec3(StateWriter& out, const Vec3& v) {
  for (int k = 0; k < 3; ++k) out.put(v[k]);
}

Vec3 getVec3(StateReader& in) {
  Vec3 v;
  for (int k = 0; k < 3; ++k) v[k] = in.get<double>();
  return v;
}

void putBody(StateWriter& out, const Body& b) {
  putVec3(out, b.pose.position);
  for (int k = 0; k < 4; ++k) out.put(b.pose.rotation.coeffs()[k]);
  putVec3(out, b.linear_velocity);
  putVec3(out, b.angular_velocity);
}

void getBody(StateReader& in, Body& b) {
  b.pose.position = getVec3(in);
  for (int k = 0; k < 4; ++k) b.pose.rotation.coeffs()[k] = in.get<double>();
  b.linear_velocity = getVec3(in);
  b.angular_velocity = getVec3(in);
}

// Springs may be moved and loads added between steps (the viewer, Python): both are state.
void putSpring(StateWriter& out, const SpringDesc& s) {
  out.putString(s.name);
  out.put(s.body);
  for (const Vec3* v : {&s.local_point, &s.target, &s.target_velocity}) putVec3(out, *v);
  out.put(s.stiffness);
  out.put(s.damping);
}

SpringDesc getSpring(StateReader& in) {
  SpringDesc s;
  s.name = in.getString();
  s.body = in.get<BodyId>();
  for (Vec3* v : {&s.local_point, &s.target, &s.target_velocity}) *v = getVec3(in);
  s.stiffness = in.get<double>();
  s.damping = in.get<double>();
  return s;
}

void putLoad(StateWriter& out, const LoadDesc& l) {
  out.putString(l.name);
  out.put(l.body);
  out.put(static_cast<int32_t>(l.kind));
  putVec3(out, l.value);
  putVec3(out, l.local_point);
  out.put(l.start);
  out.put(l.end);
}

LoadDesc getLoad(StateReader& in) {
  LoadDesc l;
  l.name = in.getString();
  l.body = in.get<BodyId>();
  const auto kind = in.get<int32_t>();
  if (kind < 0 || kind > static_cast<int32_t>(LoadDesc::Kind::AngularImpulse))
    throw Error("the state holds a load of unknown kind " + std::to_string(kind));
  l.kind = static_cast<LoadDesc::Kind>(kind);
  l.value = getVec3(in);
  l.local_point = getVec3(in);
  l.start = in.get<double>();
  l.end = in.get<double>();
  return l;
}

}  // namespace

std::string World::saveState() const {
  StateWriter out;
  out.putString(provider_->name());
  out.put(time_);
  out.put(steps_);
  out.put<uint64_t>(bodies_.size());
  for (const Body& b : bodies_) putBody(out, b);
  out.put<uint64_t>(joints_.size());
  for (const JointDesc& j : joints_) out.put(j.rest_length);
  out.put<uint64_t>(springs_.size());
  for (const SpringDesc& s : springs_) putSpring(out, s);
  out.put<uint64_t>(loads_.size());
  for (const LoadDesc& l : loads_) putLoad(out, l);
  // A world whose collision objects wait to be rebuilt has no persistence to keep: the next
  // step starts its contacts afresh, as the saved world's would.
  out.put<uint8_t>(bodies_changed_);
  collision_->saveState(out, !bodies_changed_);
  solver_->saveWarmStart(out);
  provider_->saveHistory(out);
  return out.take();
}

void World::loadState(std::string_view state) {
  StateReader in(state);
  const std::string provider = in.getString();
  if (provider != provider_->name())
    throw Error("the state was saved with friction provider '" + provider + "', this world uses '" +
                provider_->name() + "'");
  time_ = in.get<double>();
  steps_ = in.get<int64_t>();
  // A clock that a run of steps could reach: finite, from 0, far below where dt stops adding.
  if (!(time_ >= 0.0 && time_ <= 1e12))
    throw Error("the state's clock is " + std::to_string(time_) + " s, outside [0, 1e12]");
  if (steps_ < 0 || steps_ > (int64_t{1} << 53))
    throw Error("the state's step count is " + std::to_string(steps_) + ", outside [0, 2^53]");
  in.expect<uint64_t>(bodies_.size(), "bodies");
  for (Body& b : bodies_) getBody(in, b);
  in.expect<uint64_t>(joints_.size(), "joints");
  for (JointDesc& j : joints_) j.rest_length = in.get<double>();
  springs_.resize(in.count(1));
  for (SpringDesc& s : springs_) s = getSpring(in);
  loads_.resize(in.count(1));
  for (LoadDesc& l : loads_) l = getLoad(in);
  for (const SpringDesc& s : springs_) checkBody(s.body, "spring '" + s.name + "'");
  for (const LoadDesc& l : loads_) checkBody(l.body, "load '" + l.name + "'");
  // The collision objects built afresh for these poses, then given the saved persistence.
  contacts_.clear();
  bodies_changed_ = true;
  prepare();
  const bool rebuild = in.get<uint8_t>() != 0;
  collision_->loadState(in, !rebuild);
  bodies_changed_ = rebuild;
  solver_->loadWarmStart(in);
  provider_->loadHistory(in);
  if (!in.done())
    throw Error("the state has " + std::to_string(state.size() - in.offset()) +
                " bytes more than this world reads");
}

}  // namespace asperity
