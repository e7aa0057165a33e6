// The friction stage's settings (N, mu0, mu_max, w, R, reuse, texel reading) and the one range
// of each, shared by every front end: scenes, engine surfaces files, ContactFriction, the
// Python module, the CLI and the samplers all check through validate() or SettingRange::check, so a
// value out of range is refused with the same words wherever it is given.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "asperity/friction/directions.hpp"

namespace asperity {

// How a patch pixel reads the normal map and gain mask at its uv (docs/samplers.md).
enum class TexelReading {
  // The texel the pixel's centre falls in: each texel is one facet, as the paper builds its
  // materials (one facet per 1 x 1 mm texel) and as the authors' code samples its maps.
  Nearest,
  // The four texels around the uv blended before Eq. 5. Eq. 5 is nonlinear in a facet's tilt,
  // so a blend flattens facets and reads rough maps smoother than their own texels (concrete
  // about 40 % low); kept to show that difference.
  Bilinear,
};
inline constexpr std::pair<const char*, TexelReading> kTexelReadingNames[] = {
    {"nearest", TexelReading::Nearest}, {"bilinear", TexelReading::Bilinear}};

// What every provider needs to know (SPEC 3, Eq. 7).
struct FrictionSettings {
  int directions = 4;         // N
  double mu0 = 0.2;           // nominal coefficient (unit: 1)
  float mu_max = 4.0f;        // clamp of the ploughing term
  double patch_width = 0.02;  // w (m)
  int patch_resolution = 16;  // R (pixels per side)
  // Patch coherence (cpu and gl samplers): a contact whose surfaces moved by less than this
  // many patch pixels (w / R each) since its patch was sampled keeps that sample; a kept
  // sample's mu differs from a fresh one by what a sub-pixel move changes (pixel centres that
  // crossed a texel edge read the next facet): mostly below 0.005, a few hundredths at most on
  // rough maps (docs/samplers.md). 0: sample every call.
  // Samples are matched across calls by the contact's identity (bodies, shapes, key): after
  // changing a body's shapes or surfaces, call forgetHistory() (World::forgetContactHistory).
  double reuse_pixels = 0.1;
  // How each patch pixel reads the textures (cpu and gl samplers).
  TexelReading texel_reading = TexelReading::Nearest;
};

// The allowed values of one numeric setting.
struct SettingRange {
  double lo = 0.0;
  double hi = 0.0;  // 1e300 or more: no upper bound but finiteness
  bool lo_open = false;
  bool integer = false;
  // "an integer in [1, 256]", "a number in (0, 1000]", "a finite number >= 0".
  std::string describe() const;
  // Empty when `value` is allowed, else "must be an integer in [1, 256], got 512".
  std::string check(double value) const;
};

// Each field's range (docs/scene-format.md lists them).
namespace friction_range {
inline constexpr SettingRange directions{kMinDirections, kMaxDirections, false, true};
inline constexpr SettingRange mu0{0.0, 100.0};
inline constexpr SettingRange mu_max{0.0, 1000.0, true};
// m: below 1e-6 a patch is finer than float uv; above 100 no contact patch is meant.
inline constexpr SettingRange patch_width{1e-6, 100.0};
// Pixels per side: 256 x 256 fragments per surface is far past what a contact needs.
inline constexpr SettingRange patch_resolution{1.0, 256.0, false, true};
inline constexpr SettingRange reuse_pixels{0.0, 1e300};
}  // namespace friction_range

// A field out of its range: its name (the scene key) and what is wrong with it.
struct InvalidSetting {
  std::string field;    // "patch_resolution"
  std::string message;  // "must be an integer in [1, 256], got 512"
};

// The first field of `s` outside its range, in declaration order; nullopt when all are in.
std::optional<InvalidSetting> firstInvalidSetting(const FrictionSettings& s);

// Throws asperity::Error "`who`: patch_resolution must be an integer in [1, 256], got 512" for
// the first field out of its range.
void validate(const FrictionSettings& s, const std::string& who);

}  // namespace asperity
