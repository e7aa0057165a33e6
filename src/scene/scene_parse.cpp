// Scene files: the top level, "settings", and the joints, springs and loads that name bodies.
// Bodies, shapes and surfaces are read in body_parse.cpp.
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "scene/scene_common.hpp"

namespace asperity {

namespace scene {

std::string parentFolder(const std::string& file) {
  return std::filesystem::path(file).parent_path().string();
}

std::string resolvePath(const std::string& base_dir, const std::string& file) {
  const std::filesystem::path p(file);
  if (p.is_absolute() || base_dir.empty()) return p.lexically_normal().string();
  return (std::filesystem::path(base_dir) / p).lexically_normal().string();
}

void parseFrameSettings(JsonReader& r, FrameSettings& f) {
  f.mode = r.enumeration(r.renamed("frame_mode", "frame"), f.mode, kFrameModeNames);
  f.world_axis = r.direction("world_axis", f.world_axis);
  f.fallback_axis = r.direction("fallback_axis", f.fallback_axis);
  f.sliding_speed = r.number(r.renamed("sliding_speed", "auto_frame_speed"), f.sliding_speed,
                             Range::nonNegative(kHuge));
}

// A number checked against its range (an integer one included) before it becomes an int, a
// float or an int64, so a value past the target type is refused rather than converted.
static double checkedNumber(JsonReader& r, const char* key, const SettingRange& range,
                            double fallback) {
  const double value = r.number(key, fallback);
  if (const std::string bad = range.check(value); !bad.empty()) r.failAt(key, bad);
  return value;
}

void parseFrictionSettings(JsonReader& r, FrictionSettings& f) {
  f.directions =
      static_cast<int>(checkedNumber(r, "directions", friction_range::directions, f.directions));
  f.mu0 = checkedNumber(r, "mu0", friction_range::mu0, f.mu0);
  f.mu_max = static_cast<float>(checkedNumber(r, "mu_max", friction_range::mu_max, f.mu_max));
  f.patch_width = checkedNumber(r, "patch_width", friction_range::patch_width, f.patch_width);
  f.patch_resolution = static_cast<int>(
      checkedNumber(r, "patch_resolution", friction_range::patch_resolution, f.patch_resolution));
  f.reuse_pixels = checkedNumber(r, "reuse_pixels", friction_range::reuse_pixels, f.reuse_pixels);
  f.texel_reading = r.enumeration("texel_reading", f.texel_reading, kTexelReadingNames);
}

double radiansFromDegrees(double degrees) {
  return degrees * (kPi / 180.0);
}

double degreesFromRadians(double radians) {
  // The plain product, or a neighbour within a few ulps that converts back exactly.
  const double d = radians * (180.0 / kPi);
  double up = d;
  double down = d;
  for (int i = 0; i < 8; ++i) {
    if (radiansFromDegrees(up) == radians) return up;
    if (radiansFromDegrees(down) == radians) return down;
    up = std::nextafter(up, std::numeric_limits<double>::infinity());
    down = std::nextafter(down, -std::numeric_limits<double>::infinity());
  }
  return d;
}

namespace {

// "settings": every WorldSettings field, plus the friction provider's name.
void parseSettings(JsonReader r, SceneDesc& scene) {
  WorldSettings& s = scene.settings;
  s.dt = r.number("dt", s.dt, Range::leftOpen(0.0, 1.0));
  s.iterations = r.integer("iterations", s.iterations, 1, 10000);
  s.substeps = r.integer("substeps", s.substeps, 1, 1000);
  s.threads = r.integer("threads", s.threads, 0, kMaxThreads);
  s.gravity = r.vec3("gravity", s.gravity, Range::closed(-kHuge, kHuge));
  // Keys named as the C++ fields; the old "friction" and "frame" are still read.
  s.limit_surface =
      r.enumeration(r.renamed("limit_surface", "friction"), s.limit_surface, kLimitSurfaceNames);
  parseFrameSettings(r, s.frame);
  s.auto_frame_iterations = r.integer("auto_frame_iterations", s.auto_frame_iterations, 0, 1000);
  s.warm_starting = r.boolean("warm_starting", s.warm_starting);
  s.baumgarte = r.number("baumgarte", s.baumgarte, Range::closed(0.0, 1.0));
  s.linear_slop = r.number("linear_slop", s.linear_slop, Range::nonNegative(kHuge));
  s.contact_margin = r.number("contact_margin", s.contact_margin, Range::nonNegative(kHuge));
  s.max_correction_speed =
      r.number("max_correction_speed", s.max_correction_speed, Range::nonNegative(kHuge));
  s.max_speed = r.number("max_speed", s.max_speed, Range::nonNegative(kHuge));
  constexpr SettingRange kMaxPairsRange{0.0, 1e12, false, true};
  s.max_pairs = static_cast<int64_t>(
      checkedNumber(r, "max_pairs", kMaxPairsRange, static_cast<double>(s.max_pairs)));
  // SPEC 3: N, mu0, mu_max, w, R.
  parseFrictionSettings(r, s.friction);
  // Any friction provider, sampler or not; the old "sampler" is still read.
  const std::string provider = r.renamed("friction_provider", "sampler");
  scene.friction_provider = r.string(provider, scene.friction_provider);
  if (scene.friction_provider.empty())
    r.failAt(provider, "must be a friction provider name, got \"\"");
  scene.friction_model = r.enumeration("friction_model", scene.friction_model,
                                       EnumNames<FrictionModel>(kFrictionModelNames));
  r.finish();
}

// A body name that must be one of the scene's bodies.
std::string bodyName(JsonReader& r, const std::string& key, const std::set<std::string>& names) {
  const std::string name = r.requiredString(key);
  if (!names.count(name)) r.failAt(key, "unknown body \"" + name + "\"");
  return name;
}

// "joints": distance, ball, hinge and fixed joints between two named bodies.
SceneJoint parseJoint(JsonReader r, const std::set<std::string>& names) {
  SceneJoint j;
  JointDesc& d = j.desc;
  d.name = r.string("name", d.name);
  d.type = r.enumeration("type", d.type, kJointTypeNames);
  j.body_a = bodyName(r, "body_a", names);
  j.body_b = bodyName(r, "body_b", names);
  if (j.body_a == j.body_b) r.failAt("body_b", "must differ from body_a (\"" + j.body_a + "\")");
  d.anchor_a = r.vec3("anchor_a", d.anchor_a, Range::closed(-kHuge, kHuge));
  d.anchor_b = r.vec3("anchor_b", d.anchor_b, Range::closed(-kHuge, kHuge));
  d.axis_a = r.direction("axis_a", d.axis_a);
  d.axis_b = r.direction("axis_b", d.axis_b);
  // Distance joints: length(t) = rest_length + amplitude cos(2 pi frequency t + phase).
  d.rest_length = r.number("rest_length", d.rest_length, Range::nonNegative(kHuge));
  d.amplitude = r.number("amplitude", d.amplitude, Range::closed(-kHuge, kHuge));
  d.frequency = r.number("frequency", d.frequency, Range::nonNegative(kHuge));
  d.phase = r.number("phase", d.phase, Range::closed(-kHuge, kHuge));
  d.collide_connected = r.boolean("collide_connected", d.collide_connected);
  r.finish();
  return j;
}

// "springs": a damped spring from a body point to a moving world target.
SceneSpring parseSpring(JsonReader r, const std::set<std::string>& names) {
  SceneSpring s;
  SpringDesc& d = s.desc;
  d.name = r.string("name", d.name);
  s.body = bodyName(r, "body", names);
  d.local_point = r.vec3("local_point", d.local_point, Range::closed(-kHuge, kHuge));
  d.target = r.vec3("target", d.target, Range::closed(-kHuge, kHuge));
  d.target_velocity = r.vec3("target_velocity", d.target_velocity, Range::closed(-kHuge, kHuge));
  d.stiffness = r.number("stiffness", d.stiffness, Range::nonNegative(1e12));
  d.damping = r.number("damping", d.damping, Range::nonNegative(1e12));
  r.finish();
  return s;
}

// "loads": forces and torques over [start, end), impulses once at start.
SceneLoad parseLoad(JsonReader r, const std::set<std::string>& names) {
  SceneLoad l;
  LoadDesc& d = l.desc;
  d.name = r.string("name", d.name);
  l.body = bodyName(r, "body", names);
  d.kind = r.enumeration("kind", d.kind, kLoadKindNames);
  d.value = r.vec3("value", d.value, Range::closed(-1e12, 1e12));
  d.local_point =
      r.vec3(r.renamed("local_point", "point"), d.local_point, Range::closed(-kHuge, kHuge));
  d.start = r.number("start", d.start, Range::nonNegative(1e30));
  d.end = r.number("end", d.end, Range::closed(d.start, 1e30));
  r.finish();
  return l;
}

// "pairs": the friction model of contacts between two named materials, overriding the scene's
// "friction_model" for them. Each unordered pair once; contact_area needs both materials'
// "mechanical" values.
void parsePairs(JsonReader& root, SceneDesc& scene) {
  std::vector<JsonReader> entries = root.objects("pairs");
  std::map<std::pair<std::string, std::string>, size_t> seen;
  for (size_t i = 0; i < entries.size(); ++i) {
    JsonReader& r = entries[i];
    ScenePair pair;
    std::vector<JsonReader> names = r.elements("materials");
    if (!r.has("materials")) r.fail("missing key \"materials\" (two material names)");
    if (names.size() != 2)
      r.failAt("materials",
               "must name two materials (the same one twice for a material on "
               "itself), got " +
                   std::to_string(names.size()));
    if (!r.has("friction_model")) r.fail("missing key \"friction_model\"");
    pair.friction_model = r.enumeration("friction_model", pair.friction_model,
                                        EnumNames<FrictionModel>(kFrictionModelNames));
    for (size_t k = 0; k < 2; ++k) {
      if (!names[k].value().is_string())
        names[k].fail("must be a material name, got " + describeValue(names[k].value()));
      const std::string name = names[k].value().get<std::string>();
      const auto found = scene.materials.find(name);
      if (found == scene.materials.end()) {
        std::vector<std::string> known;
        for (const auto& entry : scene.materials) known.push_back(entry.first);
        names[k].fail("unknown material \"" + name + "\" (" +
                      (known.empty() ? "the scene has no \"materials\"" : oneOf(known)) + ")");
      }
      if (pair.friction_model == FrictionModel::ContactArea && !found->second.mechanical)
        names[k].fail("friction_model contact_area needs \"mechanical\" values; material \"" +
                      name + "\" has none");
      pair.materials[k] = name;
    }
    const auto key = std::minmax(pair.materials[0], pair.materials[1]);
    const auto [it, fresh] = seen.emplace(key, i);
    if (!fresh)
      r.failAt("materials", "the pair \"" + key.first + "\", \"" + key.second +
                                "\" is already given at /pairs/" + std::to_string(it->second));
    r.finish();
    scene.pairs.push_back(pair);
  }
}

// "camera": eye and target (m), vertical field of view in degrees.
SceneCamera parseSceneCamera(JsonReader r) {
  SceneCamera c;
  c.eye = r.requiredVec3("eye", Range::closed(-kHuge, kHuge));
  c.target = r.requiredVec3("target", Range::closed(-kHuge, kHuge));
  if ((c.eye - c.target).norm() < 1e-9) r.failAt("target", "must differ from eye");
  const Range fov{0.0, 180.0, true, true};
  c.fov_y = radiansFromDegrees(r.number("fov_deg", degreesFromRadians(c.fov_y), fov));
  r.finish();
  return c;
}

}  // namespace

}  // namespace scene

SceneDesc parseScene(const nlohmann::json& json, const std::string& file_for_messages) {
  using namespace scene;
  SceneDesc out;
  out.source_file = file_for_messages;
  out.base_dir = parentFolder(file_for_messages);
  JsonReader root(json, file_for_messages);
  root.setWarnings(&out.warnings);
  root.requireObject();
  parseSettings(root.object("settings"), out);
  parseMaterials(root, out);
  parseBodies(root, out);
  parsePairs(root, out);
  // Joints, springs and loads refer to bodies by name.
  std::set<std::string> names;
  for (const BodyDesc& b : out.bodies) names.insert(b.name);
  for (JsonReader& r : root.objects("joints")) out.joints.push_back(parseJoint(r, names));
  for (JsonReader& r : root.objects("springs")) out.springs.push_back(parseSpring(r, names));
  for (JsonReader& r : root.objects("loads")) out.loads.push_back(parseLoad(r, names));
  if (root.has("camera")) out.camera = parseSceneCamera(root.object("camera"));
  root.finish();
  return out;
}

SceneDesc loadScene(const std::string& path) {
  return parseScene(scene::parseJsonFile(path), path);
}

}  // namespace asperity
