// ODE with Asperity's friction (asperity/engines/ode.hpp): a flat texture changes nothing, the
// slides agree with Asperity's own solver, and bad input is an error naming it.
#include "asperity/engines/ode.hpp"

#include <gtest/gtest.h>

#include <string>

#include "engines/engine_checks.hpp"
#include "ode/ode_scene.hpp"

namespace asperity {
namespace {

using test::errorOf;

using test::flatSlab;

TEST(OdeFriction, FlatTextureLeavesOdesRunUnchanged) {
  // Boxes that cannot turn: every patch sees flat facets square to the normal, so nothing
  // changes, bit for bit.
  const auto with = ode_scene::run(flatSlab(), 1.0, true, {true});
  const auto alone = ode_scene::run(flatSlab(), 1.0, false, {true});
  EXPECT_GT(with.stats.textured, 0);
  EXPECT_EQ(with.trajectory, alone.trajectory);  // every step
  // Free boxes rock a little as they land; Asperity's model then sees the tilted flat face
  // plough (SPEC 2), which moves the slide by well under 2 %.
  const SceneDesc scene = flatSlab();
  test::expectAgreement(
      "flat", engine_setups::horizontalDistances(scene, ode_scene::run(scene, 1.0, true).positions),
      engine_setups::horizontalDistances(scene, ode_scene::run(scene, 1.0, false).positions), 0.02);
}

// The engine with Asperity's friction: its bodies' final positions.
std::map<std::string, Vec3> withAsperity(const SceneDesc& scene, double seconds) {
  return ode_scene::run(scene, seconds, true).positions;
}

TEST(OdeFriction, SlidesAgreeWithAsperitysSolverWithin25Percent) {
  test::expectAgreementOnEverySetup(withAsperity, 0.25);
}

TEST(OdeFriction, SawtoothGripsOneWayAndAnisotropyShows) {
  test::expectSenseAndAnisotropy(withAsperity);
}

// A box geom and a ray geom in a space of their own.
struct Geoms {
  Geoms() {
    dInitODE2(0);
    space = dSimpleSpaceCreate(nullptr);
    box = dCreateBox(space, 0.2, 0.2, 0.2);
    ray = dCreateRay(space, 1.0);
  }
  ~Geoms() { dSpaceDestroy(space); }
  dSpaceID space;
  dGeomID box, ray;
};

TEST(OdeFriction, BadInputIsAnErrorNamingIt) {
  const std::string dir = test::tempDir("ode_friction");
  Geoms geoms;
  // A surface that no registered geom carries: the name and the file.
  const std::string unknown = dir + "/unknown.json";
  test::writeFile(unknown, R"({"surfaces": {"box": {"gain": 1}, "ghost": {"gain": 2}}})");
  OdeFriction friction(unknown);
  friction.addGeom(geoms.box, "box");
  const std::string e1 = errorOf([&] { friction.finish(); });
  EXPECT_NE(e1.find(unknown), std::string::npos) << e1;
  EXPECT_NE(e1.find("\"ghost\""), std::string::npos) << e1;
  // A normal map that is not there: its path.
  const std::string missing = dir + "/missing.json";
  test::writeFile(missing, R"({"surfaces": {"box": {"normal_map": "textures/none.png"}}})");
  const std::string e2 = errorOf([&] { OdeFriction f(missing); });
  EXPECT_NE(e2.find(dir + "/textures/none.png"), std::string::npos) << e2;
  // Geoms Asperity cannot shape, registered twice, or without a name.
  OdeFriction plain{EngineSurfaces{}};
  EXPECT_NE(errorOf([&] { plain.addGeom(geoms.ray, "ray"); }).find("geom \"ray\" is not a plane"),
            std::string::npos);
  plain.addGeom(geoms.box, "box");
  EXPECT_NE(errorOf([&] { plain.addGeom(geoms.box, "again"); }).find("registered already"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { plain.addGeom(geoms.ray); }).find("no name"), std::string::npos);
}

}  // namespace
}  // namespace asperity
