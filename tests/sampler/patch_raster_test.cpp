// The CPU rasteriser's planar primitives (sampler/patch_raster.hpp) against a per-pixel oracle:
// whatever shortcuts the rows take (edges and depth clip that hold over the whole box, faces
// seen nearly edge-on rejected early), a pixel is covered exactly when its centre lies inside
// the polygon and within the depth clip, and keeps that primitive's depth. The depth margins it
// notes (patch coherence) are no larger than any pixel centre's distance to the clip, and a
// face moved by less keeps its coverage.
#include "sampler/patch_raster.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace asperity::patch {
namespace {

Volume testVolume() {
  Volume v;
  v.width = 0.02;
  v.resolution = 16;
  v.pixel = v.width / v.resolution;
  v.half_depth = 1e-4;
  return v;
}

// A rectangle (or its first three corners, a triangle) at `centre` with normal `n`,
// counter-clockwise seen from +z as the rasteriser takes it.
std::vector<PolygonVertex> polygon(const Vec3& centre, const Vec3& n, double spin, double a,
                                   double b, bool triangle) {
  const Vec3 any = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u0 = n.cross(any).normalized(), v0 = n.cross(u0);
  const Vec3 u = std::cos(spin) * u0 + std::sin(spin) * v0, v = n.cross(u);
  std::vector<PolygonVertex> corners(triangle ? 3 : 4);
  const double su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
  for (size_t k = 0; k < corners.size(); ++k) corners[k].p = centre + su[k] * a * u + sv[k] * b * v;
  if (n.z() < 0.0) std::reverse(corners.begin(), corners.end());
  return corners;
}

// The oracle: edge functions of the corners (top-left rule), depth on their plane.
bool insideEdgesOracle(const std::vector<PolygonVertex>& c, double x, double y, double& z) {
  const size_t count = c.size();
  for (size_t k = 0; k < count; ++k) {
    const Vec3& p = c[k].p;
    const Vec3& q = c[(k + 1) % count].p;
    const double ea = -(q.y() - p.y()), eb = q.x() - p.x();
    const double e = ea * x + eb * y - (ea * p.x() + eb * p.y());
    const bool inclusive = q.y() < p.y() || (q.y() == p.y() && q.x() < p.x());
    if (!(e > 0.0 || (e == 0.0 && inclusive))) return false;
  }
  const Vec3 normal = (c[1].p - c[0].p).cross(c[2].p - c[0].p);
  z = c[0].p.z() - (normal.x() * (x - c[0].p.x()) + normal.y() * (y - c[0].p.y())) / normal.z();
  return true;
}

bool insideOracle(const std::vector<PolygonVertex>& c, double h, double x, double y, double& z) {
  return insideEdgesOracle(c, x, y, z) && std::abs(z) <= h;
}

// Random faces: nearly facing the viewer (partly beyond the depth clip), oblique, and seen
// almost edge-on (|n.z| down to 1e-5); large and small, across the patch, its corners and edges.
struct FaceMaker {
  explicit FaceMaker(unsigned seed) : rng(seed) {}
  std::vector<PolygonVertex> next(const Volume& volume, int trial) {
    const Vec3 side = Vec3(unit(rng), unit(rng), 0.0).normalized();
    const double lean = trial % 3 == 0   ? 0.02 * std::abs(unit(rng))
                        : trial % 3 == 1 ? 1.5 * std::abs(unit(rng))
                                         : 0.5 * kPi - std::pow(10.0, -5.0 * std::abs(unit(rng)));
    const double up = unit(rng) < 0.0 ? -1.0 : 1.0;
    const Vec3 n = up * std::cos(lean) * Vec3::UnitZ() + std::sin(lean) * side;
    tilt = std::abs(n.z());
    const double size = volume.width * std::pow(10.0, 2.0 * unit(rng));
    const Vec3 centre(0.6 * volume.width * unit(rng), 0.6 * volume.width * unit(rng),
                      volume.half_depth * 2.0 * unit(rng));
    return polygon(centre, n, 3.0 * unit(rng), size * (1.1 + unit(rng)), size * (1.1 + unit(rng)),
                   trial % 4 == 0);
  }
  std::mt19937 rng;
  std::uniform_real_distribution<double> unit{-1.0, 1.0};
  double tilt = 1.0;  // of the last face: |n.z|
};

// Rasterises one face alone; false when makePlanar rejects it.
bool rasteriseFace(const Volume& volume, const std::vector<PolygonVertex>& corners,
                   SurfaceRaster& raster) {
  raster.reset(Side::B, volume.resolution);
  Planar prim;
  if (!makePlanar(volume, corners.data(), static_cast<int>(corners.size()), false, {}, prim,
                  raster.depth)) {
    return false;
  }
  raster.planars.push_back(prim);
  rasterisePlanar(volume, raster.planars.back(), 0, raster);
  return true;
}

TEST(PatchRaster, PlanarCoverageIsExactlyThePixelCentresInside) {
  const Volume volume = testVolume();
  FaceMaker faces(7);
  int covered_total = 0, rejected = 0, slivers = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const std::vector<PolygonVertex> corners = faces.next(volume, trial);
    slivers += faces.tilt < 1e-2;
    SurfaceRaster raster;
    if (!rasteriseFace(volume, corners, raster)) ++rejected;
    for (int j = 0; j < volume.resolution; ++j) {
      for (int i = 0; i < volume.resolution; ++i) {
        double z = 0.0;
        const bool inside =
            insideOracle(corners, volume.half_depth, volume.centreX(i), volume.centreX(j), z);
        const int p = j * volume.resolution + i;
        ASSERT_EQ(raster.covered(p), inside) << "trial " << trial << " pixel " << i << ", " << j;
        if (!inside) continue;
        ++covered_total;
        EXPECT_NEAR(raster.key[static_cast<size_t>(p)], z, 1e-9) << "trial " << trial;
      }
    }
  }
  // The cases the shortcuts are for were all met.
  EXPECT_GT(covered_total, 10000);
  EXPECT_GT(rejected, 100);
  EXPECT_GT(slivers, 400);
}

TEST(PatchRaster, DepthMarginsAreNoWiderThanAnyClipDecision) {
  const Volume volume = testVolume();
  const double h = volume.half_depth;
  FaceMaker faces(11);
  int wide = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const std::vector<PolygonVertex> corners = faces.next(volume, trial);
    SurfaceRaster raster;
    rasteriseFace(volume, corners, raster);
    const DepthMargins& m = raster.depth;
    wide += std::min({m.in_top, m.out_top, m.in_bottom, m.out_bottom}) > 0.1 * h;
    // Every pixel centre in the face is at least that far from each plane, on its side.
    for (int j = 0; j < volume.resolution; ++j) {
      for (int i = 0; i < volume.resolution; ++i) {
        double z = 0.0;
        if (!insideEdgesOracle(corners, volume.centreX(i), volume.centreX(j), z)) continue;
        const std::string at = "trial " + std::to_string(trial) + " z " + std::to_string(z);
        const double rounding = 1e-9 * (h + std::abs(z));  // the oracle's z, not the margins
        if (z > h) {
          ASSERT_GE(z - h, m.out_top - rounding) << at;
        } else if (z < -h) {
          ASSERT_GE(-h - z, m.out_bottom - rounding) << at;
        } else {
          ASSERT_GE(h - z, m.in_top - rounding) << at;
          ASSERT_GE(z + h, m.in_bottom - rounding) << at;
        }
      }
    }
  }
  EXPECT_GT(wide, 500);  // faces well inside, or well beyond, the clip
}

TEST(PatchRaster, FaceMovedWithinItsDepthMarginsKeepsItsCoverage) {
  const Volume volume = testVolume();
  FaceMaker faces(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int moved = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<PolygonVertex> corners = faces.next(volume, trial);
    SurfaceRaster before, after;
    rasteriseFace(volume, corners, before);
    const DepthMargins& m = before.depth;
    const double least = std::min({m.in_top, m.out_top, m.in_bottom, m.out_bottom, 1.0});
    if (!(least > 0.0)) continue;
    // The face rises and the clip deepens, each by less than half the least margin.
    const double rise = 0.49 * least * unit(faces.rng), grow = 0.49 * least * unit(faces.rng);
    for (PolygonVertex& v : corners) v.p.z() += rise;
    Volume deeper = volume;
    deeper.half_depth += grow;
    rasteriseFace(deeper, corners, after);
    ++moved;
    for (int p = 0; p < volume.resolution * volume.resolution; ++p)
      ASSERT_EQ(before.covered(p), after.covered(p)) << "trial " << trial << " pixel " << p;
  }
  EXPECT_GT(moved, 1000);
}

}  // namespace
}  // namespace asperity::patch
