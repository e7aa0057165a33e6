// What a normal map file holds, for `asperity texture inspect`: size, bit depth, texels that
// are not normals (SPEC 10), the green convention its slopes fit, and its mean slope.
#pragma once

#include <string>

#include "asperity/texture/normal_map.hpp"
#include "asperity/texture/png_io.hpp"

namespace asperity {

// Which green convention a map's slopes fit: a height field's slopes (-x/z, -y/z) are a
// gradient, whose curl is zero; read with the wrong green sign, y flips and the curl does not
// vanish. Unknown when neither reading is clearly better (flat maps, pure noise, one-axis
// profiles such as a sawtooth, whose curl is zero either way).
enum class GreenVerdict { OpenGL, DirectX, Unknown };

struct GreenFit {
  GreenVerdict verdict = GreenVerdict::Unknown;
  double curl_opengl = 0.0;   // RMS curl of the slope field read as OpenGL (1 / texel)
  double curl_directx = 0.0;  // RMS curl read as DirectX (1 / texel)
};

// A verdict is clear when one reading's RMS curl is at most this fraction of the other's.
inline constexpr double kClearCurlRatio = 0.5;

// Judges `map` decoded as OpenGL (green = +bitangent). Flat texels (z = 1) take part as zero
// slope; the field wraps at the borders like the sampler.
GreenFit judgeGreenConvention(const NormalMap& map);

// Mean of |slope| = sqrt(x^2 + y^2) / z over all texels (tan of the facet tilt; flat = 0).
double meanSlope(const NormalMap& map);

// "opengl", "directx" or "unknown".
const char* verdictName(GreenVerdict verdict);

}  // namespace asperity
