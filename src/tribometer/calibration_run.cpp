// A whole calibration (calibrate.hpp): which parameters are free, the run from a measurements
// file to the fit, and the calibrated scene written out.
#include <algorithm>
#include <string>

#include "asperity/error.hpp"
#include "asperity/scene/scene.hpp"
#include "asperity/tribometer/calibrate.hpp"
#include "asperity/world/builders.hpp"

namespace asperity {

namespace {

// Every shape of the body named `name` gets `gain`.
void setBodyGain(SceneDesc& scene, const std::string& name, double gain) {
  for (BodyDesc& body : scene.bodies)
    if (body.name == name)
      for (Shape& shape : body.shapes) shape.surface.gain = gain;
}

// A surface as a scene describes it: its texture text's source, gain and size, unresolved.
Surface describedSurface(const std::string& text, const Surface& resolved) {
  Surface s;
  if (!text.empty()) s.source = textureSource(text);
  // Scene files give axes in degrees only (the command line also takes u and v).
  for (auto& [name, value] : s.source.generator.params)
    if (value == "u" || value == "v") value = value == "u" ? "0" : "90";
  s.source.green = resolved.source.green;
  s.gain = resolved.gain;
  s.texture_size = resolved.texture_size;
  return s;
}

// The scene of the plate and the block at rest on it, with the calibration's surfaces.
SceneDesc tribometerScene(const CalibrationRun& c, const TribometerSource& source) {
  SceneDesc scene;
  scene.settings.friction = c.settings.friction;
  scene.friction_provider = c.settings.sampler;
  BodyDesc plate = groundPlaneDesc();
  plate.name = "plate";
  plate.shapes[0].surface = describedSurface(source.plate, c.surfaces.plate);
  const double h = 0.5 * c.settings.block_height, w = 0.5 * c.settings.block_size;
  BodyDesc block = boxDesc("block", Vec3(w, w, h), {Vec3(0.0, 0.0, h), Quat::Identity()});
  block.mass_override = c.settings.load / c.settings.gravity;
  block.shapes[0].surface = describedSurface(source.block, c.surfaces.block);
  scene.bodies = {plate, block};
  return scene;
}

}  // namespace

CalibrationSpec calibrationSpec(const TribometerSource& source, const std::vector<std::string>& fit,
                                const TribometerSurfaces& surfaces,
                                const TribometerSettings& settings) {
  // Named: only those; otherwise whatever the source leaves open.
  const char* names[3] = {"k_a", "k_b", "mu0"};
  const bool given[3] = {source.k_a.has_value(), source.k_b.has_value(), source.mu0.has_value()};
  bool free[3] = {!given[0], !given[1], !given[2]};
  if (!fit.empty()) {
    for (bool& f : free) f = false;
    for (const std::string& name : fit) {
      const auto it = std::find(std::begin(names), std::end(names), name);
      if (it == std::end(names))
        throw Error("--fit: unknown parameter '" + name + "' (k_a, k_b, mu0)");
      const auto j = static_cast<size_t>(it - std::begin(names));
      if (given[j])
        throw Error("--fit " + name + " and a value for it: a parameter is fitted or fixed");
      free[j] = true;
    }
  }
  CalibrationSpec spec{
      free[0], free[1], free[2], surfaces.block.gain, surfaces.plate.gain, settings.friction.mu0};
  return spec;
}

CalibrationRun calibrate(const std::string& data_file, const TribometerSource& source,
                         const std::vector<std::string>& fit, ModelKind model,
                         TribometerSettings settings, Diagnostics& diagnostics) {
  // The data, the surfaces and which parameters are free, checked before the model runs.
  CalibrationRun c;
  c.data = readMeasurements(data_file, settings.gravity);
  c.surfaces = resolveTribometerSource(source, settings, diagnostics);
  c.spec = calibrationSpec(source, fit, c.surfaces, settings);
  // The model's terms at the rows' angles, then the fit.
  std::vector<double> angles;
  for (const Measurement& m : c.data.rows) angles.push_back(m.angle_deg);
  c.terms = modelTerms(c.surfaces, settings, angles, model);
  c.result = fitCalibration(c.data, c.terms, c.spec);
  c.surfaces.block.gain = c.result.k_a;
  c.surfaces.plate.gain = c.result.k_b;
  settings.friction.mu0 = c.result.mu0;
  c.settings = settings;
  return c;
}

void writeCalibratedScene(const CalibrationRun& c, const TribometerSource& source,
                          const std::string& path) {
  // Values a scene file can hold (its ranges: gains up to 1e4, mu0 up to 100).
  if (c.result.k_a > 1e4 || c.result.k_b > 1e4 || c.result.mu0 > 100.0)
    throw Error("--write " + path + ": the fitted values lie outside what a scene holds (gains " +
                "up to 10000, mu0 up to 100): the textures cannot explain the measurements");
  // The source's scene with the fitted values, or a new scene of the rig.
  SceneDesc scene;
  if (source.scene.empty()) {
    scene = tribometerScene(c, source);
  } else {
    scene = loadScene(source.scene);
    if (c.spec.fit_mu0) scene.settings.friction.mu0 = c.result.mu0;
    if (c.spec.fit_k_a) setBodyGain(scene, source.block_body, c.result.k_a);
    if (c.spec.fit_k_b) setBodyGain(scene, source.plate_body, c.result.k_b);
  }
  saveScene(scene, path);
}

}  // namespace asperity
