// Guards against silent blow-ups: after every step the world's state is checked, and a
// non-finite pose or velocity, or a body faster than WorldSettings::max_speed, stops the run
// with a StepError naming the body, the step and the likely cause. At load time, parameters
// that cannot be simulated stably (a spring whose period is under 2 dt, a joint between bodies
// whose masses differ by more than 1e6) are reported as warnings.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "asperity/dynamics/body.hpp"
#include "asperity/error.hpp"

namespace asperity {

class World;

// Thrown by World::step when the state it produced is unusable. The message is one line:
// `step 12 (t = 0.12 s): body 'box': velocity is not finite; likely cause: ...`.
class StepError : public Error {
 public:
  StepError(const std::string& message, BodyId body, int64_t step)
      : Error(message), body_(body), step_(step) {}
  BodyId body() const { return body_; }
  int64_t step() const { return step_; }

 private:
  BodyId body_;
  int64_t step_;
};

// Mass ratio at a joint or contact above which PGS cannot converge in its iterations.
inline constexpr double kMaxStableMassRatio = 1e6;

// Throws StepError for the first dynamic body (by id) with a non-finite pose or velocity or a
// speed above world.settings().max_speed (0 = no speed limit). `step` is the step just taken.
void checkWorldState(const World& world, int64_t step);

// The likely cause of body `id`'s blow-up, as words ("spring 's' has a period of ...").
std::string likelyCause(const World& world, BodyId id);

// One line per parameter that cannot be simulated stably (springs, joint mass ratios).
std::vector<std::string> stabilityWarnings(const World& world);

}  // namespace asperity
