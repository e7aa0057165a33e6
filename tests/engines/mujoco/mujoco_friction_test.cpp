// MuJoCo with Asperity's friction (asperity/engines/mujoco.hpp): a flat texture changes
// nothing, the slides agree with Asperity's own solver, and bad input is an error naming it.
#include "asperity/engines/mujoco.hpp"

#include <gtest/gtest.h>

#include <string>

#include "engines/engine_checks.hpp"
#include "engines/mujoco/mujoco_geoms.hpp"
#include "support/test_support.hpp"
#include "mujoco/mjcf_scene.hpp"

namespace asperity {
namespace {

using mjcf_scene::Cone;
using test::errorOf;

using test::flatSlab;

TEST(MujocoFriction, FlatTextureLeavesMujocosRunUnchanged) {
  // Boxes that cannot turn: every patch sees flat facets square to the normal, so nothing
  // changes, bit for bit, on either cone.
  for (const Cone cone : {Cone::Elliptic, Cone::Pyramidal}) {
    const mjcf_scene::MjcfOptions options{cone, true};
    const auto with = mjcf_scene::run(flatSlab(), 1.0, true, options);
    const auto alone = mjcf_scene::run(flatSlab(), 1.0, false, options);
    EXPECT_GT(with.stats.textured, 0);
    EXPECT_EQ(with.trajectory, alone.trajectory);  // every step
  }
  // Free boxes pitch a little on MuJoCo's soft contacts; Asperity's model then sees the tilted
  // flat face plough (SPEC 2), which moves the slide by well under 2 %.
  for (const Cone cone : {Cone::Elliptic, Cone::Pyramidal}) {
    const SceneDesc scene = flatSlab();
    const auto with = mjcf_scene::run(scene, 1.0, true, {cone, false});
    const auto alone = mjcf_scene::run(scene, 1.0, false, {cone, false});
    test::expectAgreement("flat", engine_setups::horizontalDistances(scene, with.positions),
                          engine_setups::horizontalDistances(scene, alone.positions), 0.02);
  }
}

// The engine with Asperity's friction: its bodies' final positions.
std::map<std::string, Vec3> withAsperity(const SceneDesc& scene, double seconds) {
  return mjcf_scene::run(scene, seconds, true).positions;
}

TEST(MujocoFriction, SlidesAgreeWithAsperitysSolverWithin25Percent) {
  test::expectAgreementOnEverySetup(withAsperity, 0.25);
}

TEST(MujocoFriction, SawtoothGripsOneWayAndAnisotropyShows) {
  test::expectSenseAndAnisotropy(withAsperity);
}

// A model with a slab and a box, the box's condim given.
mjcf_scene::ModelPtr slabAndBox(const std::string& box_condim) {
  return mjcf_scene::loadModel(
      "<mujoco><worldbody><geom name='slab' type='box' size='1 1 0.05'/>"
      "<body pos='0 0 0.15'><freejoint/><geom name='box' type='box' size='0.1 0.1 0.1' condim='" +
      box_condim + "'/></body></worldbody></mujoco>");
}

TEST(MujocoFriction, ALibraryOtherThan22IsRefusedNamingBothVersions) {
  EXPECT_NO_THROW(mujoco_detail::checkMujocoVersion(mj_version(), mjVERSION_HEADER, "this"));
  EXPECT_EQ(test::errorOf([] { mujoco_detail::checkMujocoVersion(310, 222, "3.1.0"); }),
            "MuJoCo adapter: written for MuJoCo 2.2 (built with headers 222), but the library is "
            "3.1.0 (310)");
  EXPECT_NE(test::errorOf([] { mujoco_detail::checkMujocoVersion(223, 222, "2.2.3"); }), "");
}

TEST(MujocoFriction, BadInputIsAnErrorNamingIt) {
  const std::string dir = test::tempDir("mujoco_friction");
  const auto model = slabAndBox("3");
  // A surface for a geom the model lacks: the name and the file.
  const std::string unknown = dir + "/unknown.json";
  test::writeFile(unknown, R"({"surfaces": {"box": {"gain": 1}, "ghost": {"gain": 2}}})");
  const std::string e1 = errorOf([&] { MujocoFriction f(model.get(), unknown); });
  EXPECT_NE(e1.find(unknown), std::string::npos) << e1;
  EXPECT_NE(e1.find("\"ghost\""), std::string::npos) << e1;
  // A textured geom with condim 1.
  const std::string box = dir + "/box.json";
  test::writeFile(box, R"({"surfaces": {"box": {"gain": 1}}})");
  const std::string e2 = errorOf([&] { MujocoFriction f(slabAndBox("1").get(), box); });
  EXPECT_NE(e2.find("geom \"box\" has condim 1"), std::string::npos) << e2;
  EXPECT_NE(e2.find("friction needs condim 3 or more"), std::string::npos) << e2;
  // A normal map that is not there: its path.
  const std::string missing = dir + "/missing.json";
  test::writeFile(missing, R"({"surfaces": {"slab": {"normal_map": "textures/none.png"}}})");
  const std::string e3 = errorOf([&] { MujocoFriction f(model.get(), missing); });
  EXPECT_NE(e3.find(dir + "/textures/none.png"), std::string::npos) << e3;
  // mu0 belongs to the model, and only Euler's step can be split.
  test::writeFile(box, R"({"settings": {"mu0": 0.3}})");
  EXPECT_NE(errorOf([&] { MujocoFriction f(model.get(), box); }).find("mu0"), std::string::npos);
  model->opt.integrator = mjINT_RK4;
  MujocoFriction friction(model.get(), EngineSurfaces{});
  mjcf_scene::DataPtr data(mj_makeData(model.get()));
  EXPECT_NE(errorOf([&] { friction.step(data.get()); }).find("Euler"), std::string::npos);
}

}  // namespace
}  // namespace asperity
