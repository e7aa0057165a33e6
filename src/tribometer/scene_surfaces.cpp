// The tribometer's surfaces from two bodies of a scene, and the scene's friction settings
// (tribometer.hpp, sceneSurfaces).
#include <string>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/tribometer/tribometer.hpp"

namespace asperity {

namespace {

// The body named `name` of the instantiated world; throws naming the scene's bodies otherwise.
const Body& namedBody(const World& world, const SceneDesc& scene, const std::string& name) {
  const BodyId id = world.findBody(name);
  if (id != kNoBody) return world.body(id);
  std::string names;
  for (const BodyDesc& b : scene.bodies) names += (names.empty() ? "" : ", ") + b.name;
  throw Error(scene.source_file + ": no body named '" + name + "' (bodies: " + names + ")");
}

// The body's first shape that names a normal map, else its first shape.
const Surface& bodySurface(const Body& body, const SceneDesc& scene) {
  if (body.shapes.empty())
    throw Error(scene.source_file + ": body '" + body.name + "' has no shapes");
  for (const Shape& s : body.shapes)
    if (s.surface.normal_map) return s.surface;
  return body.shapes.front().surface;
}

}  // namespace

TribometerSurfaces sceneSurfaces(const SceneDesc& scene, const std::string& block,
                                 const std::string& plate, TribometerSettings& settings,
                                 Diagnostics& diagnostics) {
  // Instantiating resolves every surface as a run of the scene would (files, generators, assets);
  // the provider is the scene's own only later, in the tribometer's worlds.
  SceneDesc copy = scene;
  copy.friction_provider = "constant";
  const std::unique_ptr<World> world = instantiate(copy);
  for (const std::string& w : world->diagnostics().warnings()) diagnostics.warn(w);
  TribometerSurfaces surfaces;
  surfaces.block = bodySurface(namedBody(*world, scene, block), scene);
  surfaces.plate = bodySurface(namedBody(*world, scene, plate), scene);
  // The friction the scene's runs would use.
  settings.friction = scene.settings.friction;
  settings.sampler = scene.friction_provider;
  settings.dt = scene.settings.dt;
  settings.iterations = scene.settings.iterations;
  return surfaces;
}

}  // namespace asperity
