// Calibration: the gains k_A, k_B and the nominal mu0 of Eq. 7 fitted to measurements of a
// material pair (docs/calibration.md).
//
// Eq. 7 is linear in them: in the direction a block slides, mu = mu0 + k_A A + k_B B, where A and
// B are the model's terms of the block's and the plate's textures in that direction. The terms
// are what a simulation will use: the mean coefficient the sampler gives the contacts of a flat
// block sliding on the plate at the patch settings (ModelKind::Sampler), or the whole-texture
// cone of `asperity cone` (ModelKind::Cone). Directions are the tribometer's (tribometer.hpp):
// the block slides along angle_deg from the plate's +u toward +v.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "asperity/tribometer/tribometer.hpp"

namespace asperity {

// What a measurements file holds (its header line).
enum class MeasurementKind {
  Mu,            // angle_deg,mu
  TiltAngle,     // angle_deg,tilt_deg: a tilt table's sliding angle; mu = tan(tilt)
  SlideDistance  // angle_deg,speed,distance: a block launched at speed (m/s) slid distance (m)
};

struct Measurement {
  int line = 0;  // in the file, for messages
  double angle_deg = 0.0;
  double mu = 0.0;  // measured, or derived from a tilt or a slide
};

struct Measurements {
  std::string file;  // for messages
  MeasurementKind kind = MeasurementKind::Mu;
  std::vector<Measurement> rows;
};

// Reads CSV text: a header (above), then one row per line; empty lines and lines starting with
// '#' are skipped. A slide of distance d from speed v is mu = v^2 / (2 g d): the block
// decelerates at mu g (the drag test shows the solver delivers the sampler's mu). Throws
// asperity::Error `file:line: what` for a bad header, a malformed number, NaN, a negative mu, a
// tilt outside [0, 90) degrees, a speed or distance not > 0, or no rows.
Measurements parseMeasurements(const std::string& text, const std::string& file,
                               double gravity = 9.81);
// The same from a file; throws naming the file when it cannot be read.
Measurements readMeasurements(const std::string& path, double gravity = 9.81);

enum class ModelKind { Sampler, Cone };

// The model's terms for each angle: mu = mu0 + k_A block[i] + k_B plate[i].
struct ModelTerms {
  std::vector<double> block;
  std::vector<double> plate;
};

// The sampler's terms: the drag test's mu_model (tribometer.hpp: the load-weighted mean
// coefficient the sampler gave the block's contacts against the slide, over settings.tracks
// tracks) with unit gain on one side and mu0 = 0 (settings: block, patch, sampler, tracks,
// threads). Static placements were tried: a resting block samples other texels than a sliding
// one (a grid of them lined up with a sawtooth's teeth), and its terms differed from the
// tribometer's by up to 5 %. The
// cone's terms: flatPatchCone of each texture alone, along the direction opposite the slide, in
// each texture's own axes (texture rotations applied).
ModelTerms modelTerms(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                      std::span<const double> angles_deg, ModelKind kind);

// Which parameters are free; the fixed ones keep the values given.
struct CalibrationSpec {
  bool fit_k_a = true, fit_k_b = true, fit_mu0 = true;
  double k_a = 1.0, k_b = 1.0, mu0 = 0.0;
};

struct CalibrationResult {
  double k_a = 0.0, k_b = 0.0, mu0 = 0.0;
  std::vector<double> model;     // the fitted mu per row
  std::vector<double> residual;  // measured - model, per row
  double rms_residual = 0.0;
};

// Least squares over the rows with every parameter >= 0 (the best of the free parameters'
// subsets, the others at 0, when the unconstrained fit has a negative one). Throws
// asperity::Error naming the row for a mu below a fixed mu0, and naming the parameters when the
// measured directions cannot tell them apart (fix one or fit fewer) or none is free.
CalibrationResult fitCalibration(const Measurements& data, const ModelTerms& terms,
                                 const CalibrationSpec& spec);

// The free parameters: those `fit` names ("k_a", "k_b", "mu0"), or when it is empty every one
// that `source` does not give; the fixed ones at the values the source gives, else the scene's
// (or `asperity cone`'s defaults), as resolved into `surfaces` and `settings`. Throws
// asperity::Error for an unknown name, or one both named and given.
CalibrationSpec calibrationSpec(const TribometerSource& source, const std::vector<std::string>& fit,
                                const TribometerSurfaces& surfaces,
                                const TribometerSettings& settings);

// A whole calibration, as `asperity calibrate` and Python run it.
struct CalibrationRun {
  Measurements data;
  TribometerSurfaces surfaces;  // with the fitted gains
  TribometerSettings settings;  // with the fitted mu0
  ModelTerms terms;
  CalibrationSpec spec;
  CalibrationResult result;
};
// Reads `data_file`, resolves the source (tribometer.hpp), computes the model's terms at the
// rows' angles and fits. `settings` gives the rig, patch and threads (the scene's friction
// replaces it when the source names a scene). Throws asperity::Error as the steps do.
CalibrationRun calibrate(const std::string& data_file, const TribometerSource& source,
                         const std::vector<std::string>& fit, ModelKind model,
                         TribometerSettings settings, Diagnostics& diagnostics);

// Writes a scene with the fitted values: the source's scene with mu0 and the two bodies' gains
// (every shape of each) replaced where fitted, or, for textures, a scene of the plate and the
// block at rest on it with the calibrated surfaces and friction settings. Throws asperity::Error
// naming the path when it cannot be written.
void writeCalibratedScene(const CalibrationRun& calibration, const TribometerSource& source,
                          const std::string& path);

}  // namespace asperity
