// JsonReader: type and range checks, JSON pointers in messages, syntax errors with line:column.
#include "scene/json_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "asperity/error.hpp"
#include "support/test_support.hpp"

namespace asperity::scene {
namespace {

using nlohmann::json;
using test::errorOf;

TEST(JsonReader, SyntaxErrorGivesLineAndColumn) {
  // The stray comma sits on line 3; the parser stops at the "]" after it (column 14).
  const std::string text = "{\n  \"a\": 1,\n  \"b\": [1, 2,]\n}\n";
  const std::string message = errorOf([&] { parseJsonText(text, "x.json"); });
  EXPECT_EQ(message.rfind("x.json:3:14: ", 0), 0u) << message;
  EXPECT_NE(message.find("syntax error"), std::string::npos) << message;
}

TEST(JsonReader, SyntaxErrorOnFirstLine) {
  const std::string message = errorOf([] { parseJsonText("{\"a\" 1}", "y.json"); });
  EXPECT_EQ(message.rfind("y.json:1:6: ", 0), 0u) << message;
}

TEST(JsonReader, TruncatedDocument) {
  const std::string message = errorOf([] { parseJsonText("{\"a\": [1,\n", "z.json"); });
  EXPECT_EQ(message.rfind("z.json:2:", 0), 0u) << message;
}

TEST(JsonReader, DeepNestingIsRefusedWithTheDepth) {
  // 100 000 nested arrays once overflowed the stack; now the 65th level is refused by name.
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(errorOf([&] { parseJsonText(deep, "x.json"); }),
            "x.json: JSON nested 65 levels deep, more than the 64 allowed");
  // Objects count the same way, and exactly the limit still parses.
  std::string objects;
  for (int i = 0; i < 100; ++i) objects += "{\"a\":";
  objects += "1" + std::string(100, '}');
  EXPECT_EQ(errorOf([&] { parseJsonText(objects, "y.json"); }),
            "y.json: JSON nested 65 levels deep, more than the 64 allowed");
  const std::string limit = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
  EXPECT_EQ(errorOf([&] { parseJsonText(limit, "z.json"); }), "");
}

TEST(JsonReader, DuplicateKeysAreErrors) {
  EXPECT_EQ(errorOf([] { parseJsonText(R"({"a": 1, "a": 2})", "d.json"); }),
            "d.json: /a: duplicate key");
  EXPECT_EQ(errorOf([] {
              parseJsonText(R"({"bodies": [{"name": "a"}, [1, {"x": 0}], {"name": "b",
                  "shapes": [], "name": "c"}]})",
                            "d.json");
            }),
            "d.json: /bodies/2/name: duplicate key");
  // The same key in different objects is fine.
  EXPECT_EQ(parseJsonText(R"([{"a": 1}, {"a": 2}])", "d.json")[1]["a"], 2);
}

TEST(JsonReader, NumbersWithRanges) {
  const json j = {{"dt", 0.01}, {"zero", 0.0}, {"neg", -0.1}, {"big", 1e300}};
  JsonReader r(j, "f.json");
  EXPECT_EQ(r.number("dt", 1.0, Range::leftOpen(0.0, 1.0)), 0.01);
  EXPECT_EQ(r.number("absent", 0.5, Range::positive()), 0.5);
  EXPECT_EQ(errorOf([&] { r.number("zero", 1.0, Range::leftOpen(0.0, 1.0)); }),
            "f.json: /zero: must be a number in (0, 1], got 0");
  EXPECT_EQ(errorOf([&] { r.number("neg", 1.0, Range::positive()); }),
            "f.json: /neg: must be a positive number, got -0.1");
  EXPECT_EQ(errorOf([&] { r.number("big", 1.0, Range::closed(0.0, 1e6)); }),
            "f.json: /big: must be at most 1000000, got 1e+300");
}

TEST(JsonReader, WrongTypesNameTheType) {
  const json j = {{"a", "1"}, {"b", true}, {"c", json::array({1, 2})}, {"d", 3}};
  JsonReader r(j, "f.json", "/settings");
  EXPECT_EQ(errorOf([&] { r.number("a", 0.0); }),
            "f.json: /settings/a: must be a finite number, got string \"1\"");
  EXPECT_EQ(errorOf([&] { r.string("b", ""); }),
            "f.json: /settings/b: must be a string, got boolean true");
  EXPECT_EQ(errorOf([&] { r.vec3("c", Vec3::Zero()); }),
            "f.json: /settings/c: must be an array of 3 numbers, got array [1,2]");
  EXPECT_EQ(errorOf([&] { r.boolean("d", false); }),
            "f.json: /settings/d: must be true or false, got 3");
}

TEST(JsonReader, IntegersRefuseFractions) {
  const json j = {{"n", 4}, {"f", 4.5}, {"w", 4.0}, {"big", 100000}};
  JsonReader r(j, "f.json");
  EXPECT_EQ(r.integer("n", 0, 1, 10), 4);
  EXPECT_EQ(errorOf([&] { r.integer("f", 0, 1, 10); }),
            "f.json: /f: must be an integer in [1, 10], got 4.5");
  EXPECT_NE(errorOf([&] { r.integer("w", 0, 1, 10); }), "");
  EXPECT_EQ(errorOf([&] { r.integer("big", 0, 1, 10000); }),
            "f.json: /big: must be an integer in [1, 10000], got 100000");
}

TEST(JsonReader, VectorComponentsHaveTheirOwnPointer) {
  const json j = {{"half_extents", {0.1, -0.1, 0.1}}};
  JsonReader r(j, "f.json", "/bodies/2/shapes/0");
  EXPECT_EQ(errorOf([&] { r.vec3("half_extents", Vec3::Zero(), Range::positive()); }),
            "f.json: /bodies/2/shapes/0/half_extents/1: must be a positive number, got -0.1");
}

TEST(JsonReader, DirectionsAreNormalisedAndNonZero) {
  const json j = {{"a", {0, 0, 2}}, {"z", {0, 0, 0}}, {"u", {0.6, 0.8, 0}}};
  JsonReader r(j, "f.json");
  EXPECT_EQ(r.direction("a", Vec3::UnitX()), Vec3::UnitZ());
  const Vec3 u = r.direction("u", Vec3::UnitX());
  EXPECT_EQ(u.x(), 0.6);  // already unit (to 1e-12): kept bit for bit
  EXPECT_EQ(errorOf([&] { r.direction("z", Vec3::UnitX()); }),
            "f.json: /z: must be a non-zero vector, got [0, 0, 0]");
}

TEST(JsonReader, Quaternions) {
  const json j = {{"q", {2, 0, 0, 0}}, {"zero", {0, 0, 0, 0}}, {"short", {1, 0, 0}}};
  JsonReader r(j, "f.json", "/bodies/0");
  const Quat q = r.quaternion("q", Quat::Identity());
  EXPECT_EQ(q.w(), 1.0);
  EXPECT_EQ(errorOf([&] { r.quaternion("zero", Quat::Identity()); }),
            "f.json: /bodies/0/zero: must be a non-zero quaternion [w, x, y, z], got [0,0,0,0]");
  EXPECT_NE(errorOf([&] { r.quaternion("short", Quat::Identity()); }).find("/bodies/0/short"),
            std::string::npos);
}

TEST(JsonReader, EnumerationsListTheChoices) {
  enum class Kind { A, B };
  const json j = {{"k", "c"}, {"ok", "b"}};
  JsonReader r(j, "f.json");
  const std::vector<std::pair<const char*, Kind>> names = {{"a", Kind::A}, {"b", Kind::B}};
  EXPECT_EQ(r.enumeration("ok", Kind::A, names), Kind::B);
  EXPECT_EQ(errorOf([&] { r.enumeration("k", Kind::A, names); }),
            "f.json: /k: must be one of \"a\", \"b\", got string \"c\"");
  EXPECT_EQ(enumName(Kind::B, names), "b");
}

TEST(JsonReader, UnknownKeysAreErrors) {
  const json j = {{"dt", 0.01}, {"dtt", 1}};
  JsonReader r(j, "f.json", "/settings");
  r.number("dt", 0.0);
  r.number("iterations", 0.0);
  EXPECT_EQ(errorOf([&] { r.finish(); }),
            "f.json: /settings/dtt: unknown key (expected one of: dt, iterations)");
}

// A renamed key is read under its old name with a warning, which readers handed out pass on;
// the old name is offered by finish() only when it was given; both names at once are an error.
TEST(JsonReader, RenamedKeysWarnAndPassTheWarningsOn) {
  const json j = {{"settings", {{"frame", "auto"}}}, {"loads", {{{"point", 1}}}}};
  std::vector<std::string> warnings;
  JsonReader r(j, "f.json");
  r.setWarnings(&warnings);
  JsonReader settings = r.object("settings");
  EXPECT_EQ(settings.renamed("frame_mode", "frame"), "frame");
  EXPECT_EQ(settings.renamed("limit_surface", "friction"), "limit_surface");
  settings.finish();  // "frame" was given, so it is known
  JsonReader load = r.objects("loads")[0];
  EXPECT_EQ(load.renamed("local_point", "point"), "point");
  EXPECT_EQ(warnings,
            (std::vector<std::string>{"f.json: /settings/frame: deprecated, use \"frame_mode\"",
                                      "f.json: /loads/0/point: deprecated, use \"local_point\""}));
  // Not given: only the new name is listed.
  const json other = {{"x", 1}};
  JsonReader o(other, "f.json");
  o.renamed("frame_mode", "frame");
  EXPECT_EQ(errorOf([&] { o.finish(); }), "f.json: /x: unknown key (expected one of: frame_mode)");
  const json both = {{"frame", "a"}, {"frame_mode", "b"}};
  JsonReader b(both, "f.json");
  EXPECT_EQ(errorOf([&] { b.renamed("frame_mode", "frame"); }),
            "f.json: /frame: deprecated name of \"frame_mode\", which is also given: keep only "
            "\"frame_mode\"");
}

TEST(JsonReader, PointerTokensAreEscaped) {
  const json j = {{"a/b~c", "x"}};
  JsonReader r(j, "f.json");
  EXPECT_EQ(errorOf([&] { r.finish(); }).rfind("f.json: /a~1b~0c: unknown key", 0), 0u);
}

TEST(JsonReader, ArraysOfObjects) {
  const json j = {{"bodies", {json::object(), 3}}};
  JsonReader r(j, "f.json");
  EXPECT_EQ(errorOf([&] { r.objects("bodies"); }), "f.json: /bodies/1: must be an object, got 3");
  const json k = {{"bodies", "x"}};
  JsonReader s(k, "f.json");
  EXPECT_EQ(errorOf([&] { s.objects("bodies"); }),
            "f.json: /bodies: must be an array, got string \"x\"");
}

TEST(JsonReader, FormatNumberRoundTrips) {
  for (double x : {0.1, -0.1, 1.0 / 3.0, 1e-300, 6.02214076e23, 0.0, -2.5}) {
    const std::string text = formatNumber(x);
    EXPECT_EQ(std::stod(text), x) << text;
  }
  EXPECT_EQ(formatNumber(-0.1), "-0.1");
  EXPECT_EQ(formatNumber(3.0), "3");
}

}  // namespace
}  // namespace asperity::scene
