// Camera matrices, projection, picking rays, framing and --camera parsing.
#include "asperity/render/camera.hpp"

#include <gtest/gtest.h>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity {
namespace {

using test::near;

TEST(Camera, TargetProjectsToTheImageCentre) {
  render::Camera c;
  c.eye = Vec3(1.0, -2.0, 1.5);
  c.target = Vec3(0.2, 0.1, 0.3);
  const Eigen::Vector3d p = c.project(c.target, 640, 480);
  EXPECT_TRUE(near(p.x(), 320.0, 0.0, 1e-3));
  EXPECT_TRUE(near(p.y(), 240.0, 0.0, 1e-3));
  EXPECT_GT(p.z(), 0.0);
  EXPECT_LT(p.z(), 1.0);
}

TEST(Camera, UpIsUpOnScreenAndRightIsRight) {
  render::Camera c;
  c.eye = Vec3(0.0, -3.0, 0.0);
  c.target = Vec3::Zero();
  // Looking along +y with z up: +z goes up the image (smaller y), +x to the right.
  EXPECT_LT(c.project(Vec3(0.0, 0.0, 0.5), 100, 100).y(), 50.0);
  EXPECT_GT(c.project(Vec3(0.5, 0.0, 0.0), 100, 100).x(), 50.0);
}

TEST(Camera, RayThroughAProjectedPointHitsIt) {
  render::Camera c;
  c.eye = Vec3(0.7, -1.3, 0.9);
  c.target = Vec3(0.0, 0.1, 0.05);
  const Vec3 point(0.15, -0.2, 0.3);
  const Eigen::Vector3d p = c.project(point, 800, 600);
  Vec3 origin, direction;
  c.ray(p.x(), p.y(), 800, 600, origin, direction);
  const Vec3 to_point = (point - origin).normalized();
  EXPECT_TRUE(near(direction.dot(to_point), 1.0, 0.0, 1e-9));
}

TEST(Camera, OrbitKeepsDistanceAndZoomScalesIt) {
  render::Camera c;
  const double d = (c.eye - c.target).norm();
  c.orbit(0.7, 0.2);
  EXPECT_TRUE(near((c.eye - c.target).norm(), d, 1e-12));
  c.zoom(0.5);
  EXPECT_TRUE(near((c.eye - c.target).norm(), 0.5 * d, 1e-12));
  const Vec3 before = c.eye - c.target;
  c.pan(0.1, 0.0);
  EXPECT_TRUE(near((c.eye - c.target - before).norm(), 0.0, 0.0, 1e-12));
}

TEST(Camera, FrameBoxKeepsEveryCornerInView) {
  const Eigen::AlignedBox3d box(Vec3(-1.0, -0.2, 0.0), Vec3(2.0, 0.4, 0.6));
  for (double aspect : {0.5, 1.0, 16.0 / 9.0}) {
    const render::Camera c = render::frameBox(box, aspect);
    const int h = 500, w = static_cast<int>(h * aspect);
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector3d p =
          c.project(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)), w, h);
      EXPECT_GE(p.x(), 0.0);
      EXPECT_LE(p.x(), w);
      EXPECT_GE(p.y(), 0.0);
      EXPECT_LE(p.y(), h);
      EXPECT_GT(p.z(), 0.0);
      EXPECT_LT(p.z(), 1.0);
    }
  }
}

TEST(Camera, ParsesSixNumbers) {
  const render::Camera c = render::parseCamera("1,-2,3.5,0,0,0.25");
  EXPECT_EQ(c.eye, Vec3(1.0, -2.0, 3.5));
  EXPECT_EQ(c.target, Vec3(0.0, 0.0, 0.25));
}

TEST(Camera, BadCameraStringsAreOneLineErrors) {
  for (const char* bad :
       {"1,2,3", "1,2,3,4,5,6,7", "1,2,x,0,0,0", "1,2,nan,0,0,0", "1,1,1,1,1,1", ""}) {
    try {
      render::parseCamera(bad, "--camera");
      FAIL() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--camera: ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace asperity
