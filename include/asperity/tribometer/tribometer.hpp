// A virtual tribometer (SPEC 12): the standard friction tests, simulated, for a block on a plate.
//
// - Tilt table: the block rests on the plate, which tilts slowly about the axis perpendicular to
//   the test direction s; mu_s(s) = tan of the tilt at which the block has slid more than 1 mm
//   along the plate, or none when it topples (or reaches the largest tilt) first.
// - Drag test: the block, guided so that it cannot turn on the plate (a tribometer's pin), is
//   pulled along s at constant speed by a stiff, critically damped spring at the middle of its
//   base; mu_k(s) = mean spring force along s over the mean normal force in steady sliding (over
//   the distance slid), or none when the block sticks in the measured window.
// - mu_model(s): the coefficient the friction provider gave the block's contacts against sliding
//   along s, the mean over the contacts and over the distance slid in the drag test's window.
//
// Directions: s = cos(a) x + sin(a) y with a = 360 k / N degrees, k = 0..N-1: the direction the
// block slides in, measured from the plate's +u toward +v (texture_rotation 0). The coefficient
// resisting that slide is the sampler's mu along -s (SPEC 1), so the tribometer's curves are
// `asperity cone`'s turned half a turn. Each run's contact frame has t = s and the box limit
// surface (SPEC 4), whose bound along t is exactly the sampled coefficient (the star polygon's
// closest-point projection would not give its radius in sliding directions where it is not
// convex). docs/tribometer.md describes the tests and their accuracy.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "asperity/geometry/surface.hpp"
#include "asperity/sampler/friction_provider.hpp"

namespace asperity {

struct SceneDesc;

// The two surfaces under test, resolved (normal maps loaded): the block's bottom face is A
// (faces -n, as in `asperity cone`), the plate B. Their gains are k_A and k_B of Eq. 7.
struct TribometerSurfaces {
  Surface block;
  Surface plate;
};

struct TribometerSettings {
  int directions = 16;          // N test directions
  double block_size = 0.1;      // side of the block's square base (m)
  double block_height = 0.025;  // m
  double load = 10.0;           // normal load: the block's weight (N)
  double gravity = 9.81;        // m/s^2
  double dt = 0.01;             // s
  int iterations = 20;          // PGS iterations per step
  // mu0, mu_max, patch width and resolution, reuse; `directions` is ignored (the box needs 4).
  FrictionSettings friction;
  std::string sampler = "cpu";  // "cpu", "cone" or "constant"
  // Runs per test and direction, each on its own track: started side by side across s, a
  // plate's texture repeat apart in all; drags pool their sums, tilts average tan(angle).
  int tracks = 4;
  bool tilt = true;               // run the tilt table
  bool drag = true;               // run the drag test
  double drag_speed = 0.1;        // m/s
  double drag_settle = 0.5;       // s before the measured window
  double drag_window = 2.0;       // s measured
  double spring_frequency = 8.0;  // Hz, natural frequency of the drag spring on the block
  double tilt_rate_deg = 0.2;     // deg/s of the slow, measured tilt
  double tilt_max_deg = 80.0;     // the largest tilt tried
  double slide_threshold = 1e-3;  // m slid that counts as sliding
  double topple_deg = 10.0;       // the block's tilt on the plate that counts as toppled
  int threads = 1;                // runs side by side (0 = every core); same results for any
};

// One tilt-table test (all its tracks).
struct TiltResult {
  std::optional<double> mu_s;  // mean over the tracks of tan(tilt at which the block slid);
                               // none: on some track it did not slide
  double angle_deg = 0.0;      // atan(mu_s), or the largest tilt a track reached
  bool toppled = false;        // on some track the block toppled
};

// One drag test (all its tracks pooled). Means are over the distance slid in the windows.
struct DragResult {
  std::optional<double> mu_k;  // none: no steady sliding in the window
  double mu_model = 0.0;       // mean coefficient of the block's contacts (linear in Eq. 7's gains)
  // The same weighted by each contact's normal force: what the friction force adds up to if
  // every contact slides at its bound. mu_k against it checks the solver; mu_model differs from
  // it by how the solver shares the block's weight among the corners (a rigid block on four
  // points can carry it in many ways), which leans a little toward the high-mu corners.
  double mu_loaded = 0.0;
  double min_speed = 0.0;  // slowest speed along s in the window (m/s)
};

struct TribometerDirection {
  double angle_deg = 0.0;
  std::optional<double> mu_s;
  std::optional<double> mu_k;
  std::optional<double> mu_model;  // none when the drag test did not run
  bool toppled = false;            // the tilt table's block toppled before sliding
};

struct TribometerResult {
  std::vector<TribometerDirection> directions;
};

// Throws asperity::Error naming the setting that is out of range.
void validateTribometerSettings(const TribometerSettings& settings);

// The single runs in the direction `angle_deg` (degrees, see above).
TiltResult runTiltTest(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                       double angle_deg);
DragResult runDragTest(const TribometerSurfaces& surfaces, const TribometerSettings& settings,
                       double angle_deg);

// Both tests (as settings.tilt and settings.drag ask) in settings.directions directions, the
// runs side by side on settings.threads threads; identical results for any thread count.
TribometerResult runTribometer(const TribometerSurfaces& surfaces,
                               const TribometerSettings& settings);

// A texture as the CLI and Python name it: a PNG path, or `gen:NAME:SEED` with optional
// parameters `gen:NAME:SEED:PARAM=VALUE,PARAM=VALUE` (256 x 256 texels unless `size=N` is
// among them). Throws asperity::Error naming the text when it is malformed.
SurfaceSource textureSource(const std::string& text);

// A surface for `text` (textureSource, resolved) with gain `gain` and `texture_size` metres per
// repeat. Throws asperity::Error naming the file or generator. Warnings go to `diagnostics`.
Surface tribometerSurface(const std::string& text, double gain, double texture_size,
                          Diagnostics& diagnostics, bool directx = false);

// The surfaces of two bodies of a scene (the first shape of each that names a normal map, else
// its first shape), resolved, and the scene's friction settings and sampler copied into
// `settings`. Throws asperity::Error naming an unknown body or one without shapes.
TribometerSurfaces sceneSurfaces(const SceneDesc& scene, const std::string& block,
                                 const std::string& plate, TribometerSettings& settings,
                                 Diagnostics& diagnostics);

// What names the two surfaces, as the CLI and Python take it: two texture texts, or two bodies
// of a scene file.
struct TribometerSource {
  std::string plate;  // texture text of B (textureSource); empty with a scene
  std::string block;  // texture text of A; empty: flat
  std::string scene;  // scene file; names the bodies below
  std::string block_body, plate_body;
  // Given: override the scene's (or the defaults k_A = k_B = 1, mu0 = 0 of `asperity cone`).
  std::optional<double> k_a, k_b, mu0;
  double texture_size = 0.256;         // metres per repeat of a texture named by text
  bool directx = false;                // PNG files' green is -bitangent
  std::optional<std::string> sampler;  // given: replaces the scene's (or the settings')
};

// The surfaces `source` names, resolved; mu0 and the sampler (and with a scene, its friction
// settings) go into `settings`. Throws asperity::Error for both or neither of a plate texture and
// a scene, a missing body name, and whatever resolving the textures or the scene throws.
TribometerSurfaces resolveTribometerSource(const TribometerSource& source,
                                           TribometerSettings& settings, Diagnostics& diagnostics);

}  // namespace asperity
