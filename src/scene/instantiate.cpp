// From a scene description to a World: resolve every surface's normal map and mask, every OBJ
// mesh, then create bodies, joints, springs and loads, and install the friction provider.
#include <algorithm>
#include <map>
#include <mutex>

#include "asperity/error.hpp"
#include "asperity/geometry/surface.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/texture/generators.hpp"
#include "asperity/texture/png_io.hpp"
#include "scene/scene_common.hpp"
#include "scene/scene_resources.hpp"

namespace asperity {

namespace scene {

namespace {

// A generator spec as one string: equal strings give equal maps.
std::string generatorKey(const GeneratorSpec& spec) {
  std::string key =
      "generator:" + spec.name + ":" + std::to_string(spec.size) + ":" + std::to_string(spec.seed);
  for (const auto& [name, value] : spec.params) key += ":" + name + "=" + value;
  return key;
}

// Generator parameters that name files are relative to the scene's folder.
GeneratorSpec resolveGeneratorPaths(GeneratorSpec spec, const std::string& base_dir) {
  for (const GeneratorInfo& g : generatorCatalog())
    if (g.name == spec.name)
      for (const GeneratorParam& p : g.params)
        if (p.kind == "path" && spec.params.count(p.name))
          spec.params[p.name] = resolvePath(base_dir, spec.params[p.name]);
  return spec;
}

}  // namespace

std::shared_ptr<const NormalMap> ResourceCache::normalMap(const Surface& surface,
                                                          Diagnostics& diagnostics) {
  // Files are keyed by their resolved path and green convention, generators by their spec.
  std::string key;
  if (!surface.source.normal_map_file.empty())
    key = "file:" + resolvePath(base_dir_, surface.source.normal_map_file) +
          (surface.source.green == GreenConvention::DirectX ? ":directx" : ":opengl");
  else if (!surface.source.generator.name.empty())
    key = generatorKey(surface.source.generator);
  else
    return nullptr;
  auto& slot = normal_maps_[key];
  if (slot) return slot;
  // Relative paths, the file's and the generator's path parameters, name files beside the scene.
  SurfaceSource resolved = surface.source;
  if (!resolved.normal_map_file.empty())
    resolved.normal_map_file = resolvePath(base_dir_, resolved.normal_map_file);
  resolved.generator = resolveGeneratorPaths(resolved.generator, base_dir_);
  slot = loadNormalMap(resolved, diagnostics);
  return slot;
}

std::shared_ptr<const GainMask> ResourceCache::mask(const std::string& file) {
  if (file.empty()) return nullptr;
  const std::string path = resolvePath(base_dir_, file);
  auto& slot = masks_[path];
  if (!slot) slot = std::make_shared<const GainMask>(loadGainMask(path));
  return slot;
}

std::shared_ptr<const ImportedAsset> ResourceCache::asset(const SceneMesh& source,
                                                          GreenConvention green,
                                                          Diagnostics& diagnostics) {
  const std::string path = resolvePath(base_dir_, source.file);
  auto& slot =
      assets_[path + ":" + formatNumber(source.scale) + ":" + std::to_string(source.simplify) +
              ":" + source.node + (green == GreenConvention::DirectX ? ":directx" : ":opengl")];
  if (slot) return slot;
  // The asset's normal map is decoded once: its invalid texels are reported then (SPEC 10).
  slot = loadSceneMesh(path, source, green);
  const AssetMaterial& material = slot->material;
  warnInvalidTexels(path + ": normal map " + material.normal_map_name, material.normal_stats,
                    diagnostics);
  return slot;
}

}  // namespace scene

// One resource cache per folder that the scenes' relative paths resolve against.
struct SceneResources::Impl {
  std::mutex mutex;
  std::map<std::string, scene::ResourceCache> caches;
};

SceneResources::SceneResources() : impl_(std::make_unique<Impl>()) {}
SceneResources::~SceneResources() = default;

namespace {

// Runs `f`, prefixing any error with the scene file and the JSON pointer of the culprit.
template <typename F>
auto withContext(const SceneDesc& scene, const std::string& pointer, F&& f) {
  try {
    return f();
  } catch (const Error& e) {
    const std::string file = scene.source_file.empty() ? "scene" : scene.source_file;
    throw Error(file + ": " + pointer + ": " + e.what());
  }
}

// A body's asset meshes; their materials' normal maps fill surfaces that name none.
BodyDesc resolveMeshes(const SceneDesc& scene, size_t index, scene::ResourceCache& cache,
                       Diagnostics& diagnostics, BodyDesc desc) {
  const std::string body_ptr = "/bodies/" + std::to_string(index);
  for (const SceneMesh& m : scene.meshes) {
    if (m.body != index) continue;
    if (m.shape >= desc.shapes.size())
      throw Error("scene mesh refers to shape " + std::to_string(m.shape) + " of body \"" +
                  desc.name + "\", which has " + std::to_string(desc.shapes.size()));
    Shape& shape = desc.shapes[m.shape];
    const std::string ptr = body_ptr + "/shapes/" + std::to_string(m.shape) + "/file";
    const auto asset = withContext(
        scene, ptr, [&] { return cache.asset(m, shape.surface.source.green, diagnostics); });
    shape.mesh = asset->mesh;
    shape.display_mesh = asset->display_mesh;
    // The asset's own normal map when the surface names none (SPEC 10), and its base colour.
    Surface& s = shape.surface;
    if (!s.normal_map && s.source.normal_map_file.empty() && s.source.generator.name.empty())
      s.normal_map = asset->material.normal_map;
    if (m.asset_base_color) {
      if (asset->material.has_base_color) s.base_color = asset->material.base_color;
      s.base_color_texture = asset->material.base_color_image;
    }
  }
  return desc;
}

// Resolves a body's surfaces (normal maps and masks) and its asset meshes.
// The mechanical values of shape k of body i: its inline surface's, else those of the material
// it names; null where there are none.
const Mechanical* mechanicalOf(const SceneDesc& scene, size_t i, size_t k) {
  const auto own = scene.surface_mechanical.find({i, k});
  if (own != scene.surface_mechanical.end()) return &own->second;
  const auto found = scene.materials.find(scene.bodies[i].shapes[k].surface.source.material);
  if (found != scene.materials.end() && found->second.mechanical) return &*found->second.mechanical;
  return nullptr;
}

BodyDesc resolveBody(const SceneDesc& scene, size_t index, scene::ResourceCache& cache,
                     Diagnostics& diagnostics) {
  BodyDesc desc = scene.bodies[index];
  const std::string body_ptr = "/bodies/" + std::to_string(index);
  for (size_t i = 0; i < desc.shapes.size(); ++i) {
    Surface& s = desc.shapes[i].surface;
    const std::string ptr = body_ptr + "/shapes/" + std::to_string(i) + "/surface";
    if (!s.normal_map)
      s.normal_map =
          withContext(scene, ptr + "/normal_map", [&] { return cache.normalMap(s, diagnostics); });
    if (!s.mask)
      s.mask = withContext(scene, ptr + "/mask", [&] { return cache.mask(s.source.mask_file); });
    if (const Mechanical* m = mechanicalOf(scene, index, i); m != nullptr && !s.mechanical)
      s.mechanical = *m;
  }
  return resolveMeshes(scene, index, cache, diagnostics, std::move(desc));
}

// Every body's description with its surfaces and meshes resolved, from the cache of the scene's
// folder; one instantiation resolves at a time per resources.
std::vector<BodyDesc> resolveBodies(const SceneDesc& scene, const InstantiateOptions& options,
                                    Diagnostics& diagnostics) {
  const auto resources = options.resources ? options.resources : std::make_shared<SceneResources>();
  auto& shared = scene::ResourcesAccess::impl(*resources);
  const std::lock_guard lock(shared.mutex);
  scene::ResourceCache& cache =
      shared.caches.try_emplace(scene.base_dir, scene.base_dir).first->second;
  std::vector<BodyDesc> resolved;
  for (size_t i = 0; i < scene.bodies.size(); ++i)
    resolved.push_back(resolveBody(scene, i, cache, diagnostics));
  return resolved;
}

// The id of a named body; the scene reader has checked the name, code-built scenes may not.
BodyId bodyId(const World& world, const std::string& name, const std::string& what) {
  const BodyId id = world.findBody(name);
  if (id == kNoBody) throw Error(what + ": unknown body \"" + name + "\"");
  return id;
}

// Joints, springs and loads, with body names turned into ids.
void createConnections(const SceneDesc& scene, World& world) {
  for (size_t i = 0; i < scene.joints.size(); ++i) {
    JointDesc d = scene.joints[i].desc;
    withContext(scene, "/joints/" + std::to_string(i), [&] {
      d.body_a = bodyId(world, scene.joints[i].body_a, "body_a");
      d.body_b = bodyId(world, scene.joints[i].body_b, "body_b");
      return world.createJoint(d);
    });
  }
  for (size_t i = 0; i < scene.springs.size(); ++i) {
    SpringDesc d = scene.springs[i].desc;
    withContext(scene, "/springs/" + std::to_string(i), [&] {
      d.body = bodyId(world, scene.springs[i].body, "body");
      return world.addSpring(d);
    });
  }
  for (size_t i = 0; i < scene.loads.size(); ++i) {
    LoadDesc d = scene.loads[i].desc;
    withContext(scene, "/loads/" + std::to_string(i), [&] {
      d.body = bodyId(world, scene.loads[i].body, "body");
      return world.addLoad(d);
    });
  }
}

// The scene's friction models: its "friction_model" and its "pairs" by material names. Throws,
// naming the shape, where the scene's contact-area model meets a surface without mechanical
// values (the pairs' materials were checked when the scene was read).
FrictionModelSettings frictionModels(const SceneDesc& scene) {
  FrictionModelSettings models;
  models.model = scene.friction_model;
  models.dt = scene.settings.dt / scene.settings.substeps;  // the impulse the solver keeps
  for (const ScenePair& p : scene.pairs)
    models.setPair(p.materials[0], p.materials[1], p.friction_model);
  if (scene.friction_model != FrictionModel::ContactArea) return models;
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    for (size_t k = 0; k < scene.bodies[i].shapes.size(); ++k) {
      if (mechanicalOf(scene, i, k) != nullptr) continue;
      const std::string& name = scene.bodies[i].shapes[k].surface.source.material;
      withContext(
          scene, "/bodies/" + std::to_string(i) + "/shapes/" + std::to_string(k) + "/surface", [&] {
            throw Error(
                "friction_model contact_area needs every surface to have \"mechanical\" values "
                "(E, nu, H, tau), its own or its material's" +
                (name.empty() ? std::string(", this one has none")
                              : "; material \"" + name + "\" has none"));
          });
    }
  }
  return models;
}

// Where the scene names its models: the pair or setting a provider that cannot serve them is
// reported at.
std::string modelsPointer(const SceneDesc& scene) {
  if (scene.friction_model != FrictionModel::Paper) return "/settings/friction_model";
  for (size_t p = 0; p < scene.pairs.size(); ++p)
    if (scene.pairs[p].friction_model != FrictionModel::Paper)
      return "/pairs/" + std::to_string(p) + "/friction_model";
  return "/settings/friction_model";
}

}  // namespace

std::unique_ptr<World> instantiate(const SceneDesc& scene, const InstantiateOptions& options) {
  auto world = std::make_unique<World>(scene.settings);
  std::unique_ptr<FrictionProvider> provider =
      withContext(scene, "/settings/friction_provider",
                  [&] { return options.providers.make(scene.friction_provider); });
  const FrictionModelSettings models = frictionModels(scene);
  withContext(scene, modelsPointer(scene), [&] { provider->setFrictionModels(models); });
  world->setFrictionProvider(std::move(provider));
  // What loading the scene found comes first among the world's warnings.
  for (const std::string& warning : scene.warnings) world->diagnostics().warn(warning);
  // Bodies, with equal surfaces and meshes sharing one resolved copy (across worlds too when
  // the caller shares its resources).
  const std::vector<BodyDesc> resolved = resolveBodies(scene, options, world->diagnostics());
  for (size_t i = 0; i < resolved.size(); ++i)
    withContext(scene, "/bodies/" + std::to_string(i),
                [&] { return world->createBody(resolved[i]); });
  createConnections(scene, *world);
  return world;
}

}  // namespace asperity
