// The tribometer's surfaces: textures named by text (a file or a generator), two bodies of a
// scene with the scene's friction settings, and either as the CLI and Python name them
// (tribometer.hpp).
#include <charconv>
#include <string>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/tribometer/tribometer.hpp"

namespace asperity {

namespace {

// Throws naming `text` unless it is a whole number in [0, 2^64).
uint64_t parseSeed(const std::string& text, const std::string& whole) {
  uint64_t seed = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), seed);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size())
    throw Error("texture '" + whole + "': seed must be a whole number, got '" + text + "'");
  return seed;
}

// `PARAM=VALUE,PARAM=VALUE` into the spec (`size` sets the texels per side).
void parseGeneratorParams(const std::string& text, const std::string& whole, GeneratorSpec& spec) {
  size_t begin = 0;
  while (begin <= text.size()) {
    const size_t end = std::min(text.find(',', begin), text.size());
    const std::string item = text.substr(begin, end - begin);
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error("texture '" + whole + "': expected PARAM=VALUE, got '" + item + "'");
    const std::string name = item.substr(0, eq), value = item.substr(eq + 1);
    if (name == "size")
      spec.size = static_cast<int>(std::min<uint64_t>(parseSeed(value, whole), 1u << 30));
    else
      spec.params[name] = value;
    begin = end + 1;
  }
}

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

SurfaceSource textureSource(const std::string& text) {
  SurfaceSource source;
  if (text.rfind("gen:", 0) != 0) {
    source.normal_map_file = text;
    return source;
  }
  // gen:NAME:SEED[:PARAMS]
  const size_t name_end = text.find(':', 4);
  if (name_end == std::string::npos || name_end == 4)
    throw Error("texture '" + text + "': expected gen:NAME:SEED[:PARAM=VALUE,...]");
  source.generator.name = text.substr(4, name_end - 4);
  const size_t seed_end = text.find(':', name_end + 1);
  source.generator.seed = parseSeed(text.substr(name_end + 1, seed_end - (name_end + 1)), text);
  if (seed_end != std::string::npos)
    parseGeneratorParams(text.substr(seed_end + 1), text, source.generator);
  return source;
}

Surface tribometerSurface(const std::string& text, double gain, double texture_size,
                          Diagnostics& diagnostics, bool directx) {
  Surface surface;
  surface.source = textureSource(text);
  if (directx) surface.source.green = GreenConvention::DirectX;
  surface.gain = gain;
  surface.texture_size = texture_size;
  resolveSurface(surface, diagnostics);
  return surface;
}

TribometerSurfaces resolveTribometerSource(const TribometerSource& source,
                                           TribometerSettings& settings, Diagnostics& diagnostics) {
  TribometerSurfaces s;
  if (!source.scene.empty()) {
    // Two bodies of a scene, with its friction; given numbers override.
    if (!source.plate.empty()) throw Error("give either B.png or --scene S --bodies A,B, not both");
    if (source.block_body.empty() || source.plate_body.empty())
      throw Error("--bodies: expected two body names A,B");
    s = sceneSurfaces(loadScene(source.scene), source.block_body, source.plate_body, settings,
                      diagnostics);
    s.block.gain = source.k_a.value_or(s.block.gain);
    s.plate.gain = source.k_b.value_or(s.plate.gain);
    settings.friction.mu0 = source.mu0.value_or(settings.friction.mu0);
    settings.sampler = source.sampler.value_or(settings.sampler);
    return s;
  }
  // Two textures (a flat block without one), with `asperity cone`'s defaults.
  if (source.plate.empty())
    throw Error("give the plate's texture B.png (or --scene S --bodies A,B)");
  s.plate = tribometerSurface(source.plate, source.k_b.value_or(1.0), source.texture_size,
                              diagnostics, source.directx);
  s.block.gain = source.k_a.value_or(1.0);
  s.block.texture_size = source.texture_size;
  if (!source.block.empty())
    s.block = tribometerSurface(source.block, s.block.gain, source.texture_size, diagnostics,
                                source.directx);
  settings.friction.mu0 = source.mu0.value_or(0.0);
  settings.sampler = source.sampler.value_or(settings.sampler);
  return s;
}

}  // namespace asperity
