// Green-convention verdict and mean slope of a normal map (see map_inspect.hpp).
#include "asperity/texture/map_inspect.hpp"

#include <cmath>
#include <vector>

namespace asperity {

namespace {

// Slopes (dh/du, dh/dv) per texel of the map read as OpenGL: s = (-x/z, -y/z). Floats: a
// 4096 x 4096 map's two fields take 128 MB, not 256.
void slopes(const NormalMap& map, std::vector<float>& sx, std::vector<float>& sy) {
  const std::vector<Vec3f>& t = map.texels();
  sx.resize(t.size());
  sy.resize(t.size());
  for (size_t k = 0; k < t.size(); ++k) {
    const double z = std::max(static_cast<double>(t[k].z()), 1e-3);
    sx[k] = static_cast<float>(-static_cast<double>(t[k].x()) / z);
    sy[k] = static_cast<float>(-static_cast<double>(t[k].y()) / z);
  }
}

}  // namespace

GreenFit judgeGreenConvention(const NormalMap& map) {
  GreenFit fit;
  const int w = map.width(), h = map.height();
  if (w < 3 || h < 3) return fit;
  std::vector<float> sx, sy;
  slopes(map, sx, sy);
  auto at = [w](const std::vector<float>& f, int i, int j) {
    return static_cast<double>(f[static_cast<size_t>(j) * static_cast<size_t>(w) + static_cast<size_t>(i)]);
  };
  // Central differences with wrap: a = d(sy)/du, b = d(sx)/dv; the OpenGL curl is a - b, the
  // DirectX one (y flipped) is -a - b.
  double gl = 0.0, dx = 0.0;
  for (int j = 0; j < h; ++j) {
    const int jm = (j + h - 1) % h, jp = (j + 1) % h;
    for (int i = 0; i < w; ++i) {
      const int im = (i + w - 1) % w, ip = (i + 1) % w;
      const double a = 0.5 * (at(sy, ip, j) - at(sy, im, j));
      const double b = 0.5 * (at(sx, i, jp) - at(sx, i, jm));
      gl += (a - b) * (a - b);
      dx += (a + b) * (a + b);
    }
  }
  const double n = static_cast<double>(w) * static_cast<double>(h);
  fit.curl_opengl = std::sqrt(gl / n);
  fit.curl_directx = std::sqrt(dx / n);
  // Clear only when one reading's curl is well below the other's (and not both ~ zero).
  const double larger = std::max(fit.curl_opengl, fit.curl_directx);
  if (larger < 1e-6) return fit;
  if (fit.curl_opengl <= kClearCurlRatio * fit.curl_directx) fit.verdict = GreenVerdict::OpenGL;
  if (fit.curl_directx <= kClearCurlRatio * fit.curl_opengl) fit.verdict = GreenVerdict::DirectX;
  return fit;
}

double meanSlope(const NormalMap& map) {
  if (map.empty()) return 0.0;
  // tan(tilt) per texel, averaged.
  double sum = 0.0;
  for (const Vec3f& m : map.texels()) {
    const double z = std::max(static_cast<double>(m.z()), 1e-3);
    const double x = m.x(), y = m.y();  // float squares are exact in double: no hypot needed
    sum += std::sqrt(x * x + y * y) / z;
  }
  return sum / static_cast<double>(map.texels().size());
}

const char* verdictName(GreenVerdict verdict) {
  switch (verdict) {
    case GreenVerdict::OpenGL:
      return "opengl";
    case GreenVerdict::DirectX:
      return "directx";
    case GreenVerdict::Unknown:
      break;
  }
  return "unknown";
}

}  // namespace asperity
