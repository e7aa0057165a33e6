// Stage names and the per-run sums of step profiles.
#include <algorithm>

#include "asperity/world/world.hpp"

namespace asperity {

const char* stageName(Stage stage) {
  static constexpr const char* kNames[kStageCount] = {"drivers",  "collide", "frames",
                                                      "friction", "solve",   "integrate"};
  return kNames[static_cast<size_t>(stage)];
}

void ProfileSums::add(const StepProfile& step) {
  ++steps;
  for (size_t i = 0; i < stage_ms.size(); ++i) stage_ms[i] += step.stage_ms[i];
  for (size_t i = 0; i < solve_ms.size(); ++i) solve_ms[i] += step.solve_ms[i];
  patch_ms += step.patch_ms;
  averaging_ms += step.averaging_ms;
  total_ms += step.total_ms;
  contacts += step.contacts;
  fallbacks += step.fallbacks;
  reused += step.reused;
  max_contacts = std::max(max_contacts, step.contacts);
}

double ProfileSums::meanMs(Stage stage) const {
  return stage_ms[static_cast<size_t>(stage)] / static_cast<double>(std::max<int64_t>(steps, 1));
}

std::vector<std::pair<std::string, double>> ProfileSums::means() const {
  const double n = static_cast<double>(std::max<int64_t>(steps, 1));
  std::vector<std::pair<std::string, double>> out = {
      {"contacts", contacts / n}, {"fallbacks", fallbacks / n}, {"reused", reused / n}};
  for (int i = 0; i < kStageCount; ++i) {
    const auto stage = static_cast<Stage>(i);
    out.emplace_back(std::string(stageName(stage)) + "_ms", meanMs(stage));
    // The provider's share of the friction stage (paper Table 1) right after it.
    if (stage == Stage::Friction) {
      out.emplace_back("patch_ms", patch_ms / n);
      out.emplace_back("averaging_ms", averaging_ms / n);
    }
    // The solve stage's parts right after it.
    if (stage == Stage::Solve) {
      for (int k = 0; k < kSolveStageCount; ++k) {
        const char* part = solveStageName(static_cast<SolveStage>(k));
        out.emplace_back("solve_" + std::string(part) + "_ms",
                         solve_ms[static_cast<size_t>(k)] / n);
      }
    }
  }
  out.emplace_back("total_ms", total_ms / n);
  return out;
}

}  // namespace asperity
