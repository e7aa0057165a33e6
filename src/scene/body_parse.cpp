// Scene files: "bodies", their shapes and the surfaces (normal maps) of those shapes.
#include <filesystem>
#include <set>

#include "asperity/error.hpp"
#include "asperity/texture/generators.hpp"
#include "scene/scene_common.hpp"

namespace asperity::scene {

namespace {

// The file `key` names, which must exist (relative to the scene's folder or absolute).
std::string existingFile(JsonReader& r, const std::string& key, const std::string& base_dir) {
  const std::string file = r.requiredString(key);
  const std::string resolved = resolvePath(base_dir, file);
  if (file.empty() || !std::filesystem::is_regular_file(resolved))
    r.failAt(key, "file not found: \"" + resolved + "\"");
  return file;
}

// "orientation": [w, x, y, z], or "euler_deg": [rx, ry, rz] about fixed x, then y, then z.
Quat orientation(JsonReader& r) {
  const bool has_quat = r.has("orientation");
  if (has_quat && r.has("euler_deg"))
    r.failAt("euler_deg", "give orientation or euler_deg, not both");
  if (!r.has("euler_deg")) return r.quaternion("orientation", Quat::Identity());
  const Vec3 e = r.vec3("euler_deg", Vec3::Zero(), Range::closed(-1e6, 1e6));
  using Eigen::AngleAxisd;
  const Quat q = AngleAxisd(radiansFromDegrees(e.z()), Vec3::UnitZ()) *
                 AngleAxisd(radiansFromDegrees(e.y()), Vec3::UnitY()) *
                 AngleAxisd(radiansFromDegrees(e.x()), Vec3::UnitX());
  return q.normalized();
}

// "params" of a generator: each must be one of the catalog's, numbers within its range.
void parseGeneratorParams(JsonReader r, const GeneratorInfo& info, GeneratorSpec& spec,
                          const std::string& base_dir) {
  for (const auto& [key, value] : r.value().items()) {
    const GeneratorParam* param = nullptr;
    std::vector<std::string> names;
    for (const GeneratorParam& p : info.params) {
      names.push_back(p.name);
      if (p.name == key) param = &p;
    }
    if (param == nullptr)
      r.failAt(key, "unknown parameter of generator \"" + info.name + "\" (expected " +
                        oneOf(names) + ")");
    if (param->kind == "path") {
      spec.params[key] = existingFile(r, key, base_dir);
    } else {
      const JsonReader number(value, r.file(), r.childPointer(key));
      spec.params[key] = formatNumber(number.asNumber(Range::closed(param->min, param->max)));
    }
  }
}

// "normal_map": {"generator": name, "params": {...}, "size": texels, "seed": n}.
GeneratorSpec parseGenerator(JsonReader r, const std::string& base_dir) {
  GeneratorSpec spec;
  spec.name = r.requiredString("generator");
  const GeneratorInfo* info = nullptr;
  std::vector<std::string> names;
  for (const GeneratorInfo& g : generatorCatalog()) {
    names.push_back(g.name);
    if (g.name == spec.name) info = &g;
  }
  if (info == nullptr)
    r.failAt("generator",
             "unknown generator \"" + spec.name + "\" (expected " + oneOf(names) + ")");
  parseGeneratorParams(r.object("params"), *info, spec, base_dir);
  spec.size = r.integer("size", spec.size, 1, kMaxTextureSize);
  spec.seed = r.unsignedInteger("seed", spec.seed);
  r.finish();
  return spec;
}

// "height_map": FILE and "height_scale" (SPEC 13) stand in for a normal map: the generator
// height_map over the surface's texture_size.
void parseHeightMap(JsonReader& r, const std::string& base_dir, Surface& s) {
  const double scale = r.number("height_scale", 0.0, Range::closed(0.0, 1e3));
  if (!r.has("height_map")) {
    if (r.has("height_scale")) r.failAt("height_scale", "given without a height_map");
    return;
  }
  if (r.has("normal_map")) r.failAt("height_map", "give either normal_map or height_map, not both");
  GeneratorSpec& spec = s.source.generator;
  spec.name = "height_map";
  spec.params["file"] = existingFile(r, "height_map", base_dir);
  spec.params["height_scale"] = formatNumber(scale);
  spec.params["texture_size"] = formatNumber(s.texture_size);
}

}  // namespace

// "surface": the normal map (file or generator), its mapping, gain k and mask (SPEC 3, 6), and
// the base colour it is drawn with.
Surface parseSurface(JsonReader r, const std::string& base_dir) {
  Surface s;
  if (r.has("normal_map")) {
    const nlohmann::json& v = r.value().at("normal_map");
    if (v.is_string())
      s.source.normal_map_file = existingFile(r, "normal_map", base_dir);
    else if (v.is_object())
      s.source.generator = parseGenerator(r.object("normal_map"), base_dir);
    else
      r.failAt("normal_map",
               "must be a PNG file name or a generator object, got " + describeValue(v));
  }
  s.source.green = r.boolean("directx", false) ? GreenConvention::DirectX : GreenConvention::OpenGL;
  s.gain = r.number("gain", s.gain, Range::closed(0.0, 1e4));
  s.texture_size = r.number("texture_size", s.texture_size, Range::positive(kHuge));
  parseHeightMap(r, base_dir, s);
  s.texture_rotation =
      radiansFromDegrees(r.number("texture_rotation_deg", 0.0, Range::closed(-1e6, 1e6)));
  if (r.has("mask")) s.source.mask_file = existingFile(r, "mask", base_dir);
  // Linear RGB albedo for the renderer; no effect on friction.
  s.base_color = r.vec3("base_color", s.base_color, Range::closed(0.0, 1.0));
  r.finish();
  return s;
}

namespace {

// "mechanical": a preset's name, or {"E": Pa, "nu": 1, "H": Pa (0 = no plastic limit),
// "tau": Pa}. Absent: none.
std::optional<Mechanical> parseMechanical(JsonReader& r, const std::string& key) {
  if (!r.has(key)) return std::nullopt;
  const nlohmann::json& v = r.value().at(key);
  if (v.is_string()) {
    const std::string name = r.string(key, "");
    for (const Mechanical& p : mechanicalPresets())
      if (p.name == name) return p;
    std::string known;
    for (const Mechanical& p : mechanicalPresets()) known += (known.empty() ? "" : ", ") + p.name;
    r.failAt(key, "unknown mechanical preset \"" + name + "\" (known: " + known + ")");
  }
  if (!v.is_object())
    r.failAt(key,
             "must be a preset name or {\"E\", \"nu\", \"H\", \"tau\"}, got " + describeValue(v));
  JsonReader o = r.object(key);
  constexpr double kPascals = 1e13;  // above any solid's modulus (diamond: 1.2e12 Pa)
  Mechanical m;
  m.name = "custom";
  m.modulus = o.requiredNumber("E", Range::positive(kPascals));
  m.poisson = o.requiredNumber("nu", Range::closed(0.0, 0.5));
  m.hardness = o.number("H", 0.0, Range::nonNegative(kPascals));
  m.shear = o.requiredNumber("tau", Range::positive(kPascals));
  o.finish();
  return m;
}

}  // namespace

// The JSON of a surface entry less its "mechanical" key, read into `mechanical`: what both a
// materials entry and an inline surface take beside a surface's keys.
JsonReader withoutMechanical(JsonReader& r, std::optional<Mechanical>& mechanical,
                             nlohmann::json& rest) {
  mechanical = parseMechanical(r, "mechanical");
  if (!mechanical) return r;
  rest = r.value();
  rest.erase("mechanical");
  return JsonReader(rest, r.file(), r.pointer());
}

namespace {

// A shape's "surface": an object, or the name of an entry of "materials" (a copy of that entry).
// `names_color` tells whether it gives a base colour.
// An inline surface's "mechanical" values go to scene.surface_mechanical.
Surface shapeSurface(JsonReader& r, SceneDesc& scene, size_t body, size_t shape,
                     bool& names_color) {
  const nlohmann::json* v = r.has("surface") ? &r.value().at("surface") : nullptr;
  if (v && !v->is_string() && !v->is_object())
    r.failAt("surface", "must be an object or the name of a material, got " + describeValue(*v));
  if (!v || v->is_object()) {
    JsonReader object = r.object("surface");
    std::optional<Mechanical> mechanical;
    nlohmann::json rest;
    const JsonReader surface = withoutMechanical(object, mechanical, rest);
    if (mechanical) scene.surface_mechanical[{body, shape}] = *mechanical;
    names_color = surface.value().contains("base_color");
    return parseSurface(surface, scene.base_dir);
  }
  // A name: one of the table's, listed when it is not.
  const std::string name = v->get<std::string>();
  const auto found = scene.materials.find(name);
  if (found == scene.materials.end()) {
    std::vector<std::string> known;
    for (const auto& entry : scene.materials) known.push_back(entry.first);
    r.failAt("surface", "unknown material \"" + name + "\" (" +
                            (known.empty() ? "the scene has no \"materials\"" : oneOf(known)) +
                            ")");
  }
  names_color = found->second.names_base_color;
  return found->second.surface;
}

// The mesh of a convex hull or triangle mesh shape: asset file, scale, simplification target,
// node.
SceneMesh parseMeshSource(JsonReader& r, const std::string& key, const std::string& base_dir) {
  SceneMesh m;
  m.file = existingFile(r, key, base_dir);
  m.scale = r.number("scale", m.scale, Range::positive(kHuge));
  m.simplify = r.integer("simplify", m.simplify, 0, 10000000);
  m.node = r.string("node", m.node);
  return m;
}

// "points" of a convex hull, at least 4 of them.
std::shared_ptr<const TriangleMeshData> parsePoints(JsonReader& r) {
  auto mesh = std::make_shared<TriangleMeshData>();
  for (const JsonReader& p : r.elements("points"))
    mesh->vertices.push_back(p.asVec3(Range::closed(-kHuge, kHuge)));
  if (mesh->vertices.size() < 4)
    r.failAt("points",
             "a convex hull needs at least 4 points, got " + std::to_string(mesh->vertices.size()));
  return mesh;
}

// Where a hull's or mesh's triangles come from, the one statement of the rule: every shape that
// reads an asset names it with "file" (a hull's old "mesh" is still read, deprecated); a convex
// hull takes exactly one of "file" and inline "points".
void parseTriangles(JsonReader& r, Shape& s, SceneDesc& scene, size_t body, size_t shape) {
  const bool hull = s.type == ShapeType::ConvexHull;
  const std::string file_key = hull ? r.renamed("file", "mesh") : "file";
  if (hull && r.has("points") == r.has(file_key))
    r.fail("a convex hull needs exactly one of \"points\" and \"" + file_key + "\", got " +
           (r.has("points") ? "both" : "neither"));
  if (hull && r.has("points")) {
    s.mesh = parsePoints(r);
    return;
  }
  SceneMesh m = parseMeshSource(r, file_key, scene.base_dir);
  m.body = body;
  m.shape = shape;
  scene.meshes.push_back(m);
}

// The fields that only one shape type has.
void parseGeometry(JsonReader& r, Shape& s, SceneDesc& scene, size_t body, size_t shape) {
  const Range length = Range::positive(kHuge);
  switch (s.type) {
    case ShapeType::Box:
      s.half_extents = r.requiredVec3("half_extents", length);
      break;
    case ShapeType::Sphere:
      s.radius = r.requiredNumber("radius", length);
      break;
    case ShapeType::Capsule:
    case ShapeType::Cylinder:
      s.radius = r.requiredNumber("radius", length);
      s.half_height = r.requiredNumber("half_height", length);
      break;
    case ShapeType::Plane:
      s.plane_normal = r.direction("normal", s.plane_normal);
      s.plane_offset = r.number("offset", s.plane_offset, Range::closed(-kHuge, kHuge));
      break;
    case ShapeType::ConvexHull:
    case ShapeType::TriangleMesh:
      parseTriangles(r, s, scene, body, shape);
      break;
  }
}

Shape parseShape(JsonReader r, SceneDesc& scene, size_t body, size_t shape) {
  Shape s;
  if (!r.has("type")) r.fail("missing key \"type\"");
  s.type = r.enumeration("type", s.type, kShapeTypeNames);
  s.local.position = r.vec3("position", s.local.position, Range::closed(-kHuge, kHuge));
  s.local.rotation = orientation(r);
  s.density = r.number("density", s.density, Range::positive(1e6));
  parseGeometry(r, s, scene, body, shape);
  bool names_color = false;
  s.surface = shapeSurface(r, scene, body, shape, names_color);
  // An asset's own base colour shows unless the surface names one.
  if (!scene.meshes.empty() && scene.meshes.back().body == body &&
      scene.meshes.back().shape == shape)
    scene.meshes.back().asset_base_color = !names_color;
  r.finish();
  return s;
}

BodyDesc parseBody(JsonReader r, SceneDesc& scene, size_t index) {
  BodyDesc b;
  b.name = r.requiredString("name");
  if (b.name.empty()) r.failAt("name", "must not be empty");
  b.type = r.enumeration("type", b.type, kBodyTypeNames);
  b.pose.position = r.vec3("position", b.pose.position, Range::closed(-kHuge, kHuge));
  b.pose.rotation = orientation(r);
  b.linear_velocity = r.vec3("linear_velocity", b.linear_velocity, Range::closed(-kHuge, kHuge));
  b.angular_velocity = r.vec3("angular_velocity", b.angular_velocity, Range::closed(-kHuge, kHuge));
  b.mass_override = r.number("mass", 0.0, Range::positive(kHuge));
  b.frame_axis = r.direction("frame_axis", b.frame_axis);
  // Shapes; a plane bounds a half-space and so only a static body can hold one.
  std::vector<JsonReader> shapes = r.objects("shapes");
  for (size_t i = 0; i < shapes.size(); ++i) {
    b.shapes.push_back(parseShape(shapes[i], scene, index, i));
    if (b.shapes.back().type == ShapeType::Plane && b.type != BodyType::Static)
      shapes[i].failAt("type", "a plane can only belong to a static body");
  }
  if (b.type == BodyType::Dynamic && b.shapes.empty())
    r.fail("a dynamic body needs at least one shape");
  r.finish();
  return b;
}

}  // namespace

void parseMaterials(JsonReader& root, SceneDesc& scene) {
  JsonReader table = root.object("materials");
  for (const auto& entry : table.value().items()) {
    const std::string& name = entry.key();
    if (name.empty()) table.failAt(name, "a material needs a non-empty name");
    // Each entry is a surface object; the shapes that name it keep the name for saving.
    JsonReader entry_reader = table.object(name);
    SceneMaterial& m = scene.materials[name];
    // The rest of the entry is a surface.
    nlohmann::json rest;
    const JsonReader surface = withoutMechanical(entry_reader, m.mechanical, rest);
    m.names_base_color = surface.value().contains("base_color");
    m.surface = parseSurface(surface, scene.base_dir);
    m.surface.source.material = name;
  }
  table.finish();
}

void parseBodies(JsonReader& root, SceneDesc& scene) {
  std::set<std::string> names;
  std::vector<JsonReader> bodies = root.objects("bodies");
  for (size_t i = 0; i < bodies.size(); ++i) {
    scene.bodies.push_back(parseBody(bodies[i], scene, i));
    if (!names.insert(scene.bodies.back().name).second)
      bodies[i].failAt("name", "duplicate body name \"" + scene.bodies.back().name + "\"");
  }
}

}  // namespace asperity::scene
