// The C face of ContactFriction: the same numbers as the C++ class, statuses and messages for
// bad input, and a header that compiles as C (c_header_check.c).
#include "asperity/c/contact_friction.h"

#include <gtest/gtest.h>

#include <string>

#include "asperity/engines/contact_friction.hpp"
#include "asperity/world/builders.hpp"

extern "C" int asperity_c_header_check(void);

namespace asperity {
namespace {

// A handle with a rough ground (object 0) and a cube (object 1) resting on it.
asperity_friction* groundAndCube(const char* normal_map) {
  asperity_friction_settings settings;
  asperity_friction_default_settings(&settings);
  settings.directions = 8;
  settings.provider = "cpu";
  asperity_friction* h = nullptr;
  EXPECT_EQ(asperity_friction_create(&settings, &h), ASPERITY_OK);
  asperity_shape plane;
  asperity_friction_default_shape(&plane);
  plane.type = ASPERITY_SHAPE_PLANE;
  plane.normal_map = normal_map;
  plane.gain = 2.0;
  asperity_shape cube;
  asperity_friction_default_shape(&cube);
  uint32_t ground_id = 9, cube_id = 9;
  EXPECT_EQ(asperity_friction_add_object(h, "ground", &plane, 1, &ground_id), ASPERITY_OK)
      << asperity_friction_error(h);
  EXPECT_EQ(asperity_friction_add_object(h, "cube", &cube, 1, &cube_id), ASPERITY_OK);
  EXPECT_EQ(ground_id, 0u);
  EXPECT_EQ(cube_id, 1u);
  const double zero[3] = {0, 0, 0}, up[3] = {0, 0, 0.1}, identity[4] = {1, 0, 0, 0};
  EXPECT_EQ(asperity_friction_set_state(h, 0, zero, identity, zero, zero), ASPERITY_OK);
  EXPECT_EQ(asperity_friction_set_state(h, 1, up, identity, zero, zero), ASPERITY_OK);
  return h;
}

asperity_contact contactUnderCube() {
  asperity_contact c{};
  c.object_a = 1;
  c.object_b = 0;
  c.point[0] = 0.01;
  c.normal[2] = 1.0;
  c.depth = 1e-4;
  c.key = 1;
  return c;
}

TEST(ContactFrictionC, GivesTheNumbersOfTheCppClass) {
  EXPECT_EQ(asperity_c_header_check(), 1);
  asperity_friction* h = groundAndCube("gen:gaussian:sx=0.3,sy=1");
  const asperity_contact c = contactUnderCube();
  asperity_contact_friction out{};
  ASSERT_EQ(asperity_friction_compute(h, &c, 1, &out), ASPERITY_OK) << asperity_friction_error(h);
  EXPECT_STREQ(asperity_friction_warnings(h), "");  // a generated map has only normals
  asperity_friction_destroy(h);

  // The same set-up through the C++ class.
  ContactFrictionSettings settings;
  settings.provider = "cpu";
  settings.friction.directions = 8;
  ContactFriction friction(settings);
  ObjectDesc ground{"ground", groundPlaneDesc().shapes, Vec3::Zero()};
  ground.shapes[0].surface.source.generator = {"gaussian", {{"sx", "0.3"}, {"sy", "1"}}};
  ground.shapes[0].surface.gain = 2.0;
  resolveSurface(ground.shapes[0].surface, friction.diagnostics());
  friction.addObject(ground);
  ObjectDesc cube{"cube", {Shape{}}, Vec3::Zero()};
  friction.addObject(cube);
  friction.setState(1, {Transform{Vec3(0, 0, 0.1), Quat::Identity()}});
  EngineContact e;
  e.object_a = 1;
  e.object_b = 0;
  e.point = Vec3(0.01, 0, 0);
  e.depth = 1e-4;
  e.key = 1;
  const ContactFrictionResult r = friction.compute({&e, 1})[0];
  ASSERT_EQ(out.directions, 8);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(out.mu[k], r.mu.mu[static_cast<size_t>(k)]) << k;
  EXPECT_EQ(out.bounds[0], r.bounds.mu_pos_t);
  EXPECT_EQ(out.bounds[3], r.bounds.mu_neg_b);
  EXPECT_EQ(out.t[0], r.t.x());
  EXPECT_GT(out.bounds[1], out.bounds[0]);  // rougher along v (b) than along u (t)
}

TEST(ContactFrictionC, BadInputGivesAStatusAndAMessage) {
  asperity_friction_settings settings;
  asperity_friction_default_settings(&settings);
  settings.provider = "magic";
  asperity_friction* bad = nullptr;
  EXPECT_EQ(asperity_friction_create(&settings, &bad), ASPERITY_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(asperity_friction_error(bad)).find("magic"), std::string::npos);
  const asperity_contact c = contactUnderCube();
  asperity_contact_friction out{};
  EXPECT_NE(asperity_friction_compute(bad, &c, 1, &out), ASPERITY_OK);
  asperity_friction_destroy(bad);

  // A missing texture names its path.
  asperity_friction_default_settings(&settings);
  asperity_friction* h = nullptr;
  ASSERT_EQ(asperity_friction_create(&settings, &h), ASPERITY_OK);
  asperity_shape plane;
  asperity_friction_default_shape(&plane);
  plane.type = ASPERITY_SHAPE_PLANE;
  plane.normal_map = "no/such/texture.png";
  uint32_t id = 0;
  EXPECT_EQ(asperity_friction_add_object(h, "ground", &plane, 1, &id), ASPERITY_ERROR_NOT_FOUND);
  EXPECT_NE(std::string(asperity_friction_error(h)).find("no/such/texture.png"), std::string::npos);
  // An unknown object in a contact, and an unknown generator.
  EXPECT_EQ(asperity_friction_compute(h, &c, 1, &out), ASPERITY_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(asperity_friction_error(h)).find("not registered"), std::string::npos);
  plane.normal_map = "gen:nonesuch";
  EXPECT_EQ(asperity_friction_add_object(h, "ground", &plane, 1, &id),
            ASPERITY_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(asperity_friction_error(h)).find("nonesuch"), std::string::npos);
  EXPECT_EQ(asperity_friction_compute(nullptr, &c, 1, &out), ASPERITY_ERROR_INVALID_ARGUMENT);
  asperity_friction_destroy(h);
}

}  // namespace
}  // namespace asperity
