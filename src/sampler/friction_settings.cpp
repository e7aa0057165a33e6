// The ranges of the friction settings and their one check (asperity/sampler/friction_settings.hpp).
#include "asperity/sampler/friction_settings.hpp"

#include <cmath>

#include "asperity/error.hpp"
#include "math/number_text.hpp"

namespace asperity {

std::string SettingRange::describe() const {
  if (hi >= 1e300)
    return std::string("a finite number ") + (lo_open ? "> " : ">= ") + formatNumber(lo);
  return std::string(integer ? "an integer in " : "a number in ") + (lo_open ? "(" : "[") +
         formatNumber(lo) + ", " + formatNumber(hi) + "]";
}

std::string SettingRange::check(double value) const {
  const bool above_lo = lo_open ? value > lo : value >= lo;
  const bool ok =
      std::isfinite(value) && above_lo && value <= hi && (!integer || value == std::trunc(value));
  return ok ? std::string() : "must be " + describe() + ", got " + formatNumber(value);
}

std::optional<InvalidSetting> firstInvalidSetting(const FrictionSettings& s) {
  const std::pair<const char*, std::string> checks[] = {
      {"directions", friction_range::directions.check(s.directions)},
      {"mu0", friction_range::mu0.check(s.mu0)},
      {"mu_max", friction_range::mu_max.check(static_cast<double>(s.mu_max))},
      {"patch_width", friction_range::patch_width.check(s.patch_width)},
      {"patch_resolution", friction_range::patch_resolution.check(s.patch_resolution)},
      {"reuse_pixels", friction_range::reuse_pixels.check(s.reuse_pixels)},
  };
  for (const auto& [field, message] : checks)
    if (!message.empty()) return InvalidSetting{field, message};
  return std::nullopt;
}

void validate(const FrictionSettings& s, const std::string& who) {
  if (const auto bad = firstInvalidSetting(s))
    throw Error(who + ": " + bad->field + " " + bad->message);
}

}  // namespace asperity
