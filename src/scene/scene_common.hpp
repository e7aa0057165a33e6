// What the scene reader and writer share: the JSON names of enumerations, path resolution
// against the scene's folder, and exact degree <-> radian conversion for round trips.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "asperity/contact_area/mechanical.hpp"
#include "asperity/scene/scene.hpp"
#include "scene/json_reader.hpp"

namespace asperity::scene {

// The enumerations' names live beside them (kLimitSurfaceNames, kFrameModeNames, ...).

// Largest length, mass, speed... a scene may hold; keeps overflow out of the step.
inline constexpr double kHuge = 1e6;

// The folder of a file ("" for a bare name).
std::string parentFolder(const std::string& file);
// `file` if absolute, else base_dir/file (lexically normalised).
std::string resolvePath(const std::string& base_dir, const std::string& file);

// Degrees written so that reading them back gives the same radians bit for bit.
double degreesFromRadians(double radians);
double radiansFromDegrees(double degrees);

// The friction settings of a "settings" object (directions, mu0, mu_max, patch_width,
// patch_resolution, reuse_pixels, texel_reading) over `f`: types checked here, ranges by the
// one check every front end shares (asperity/sampler/friction_settings.hpp), at the key.
void parseFrictionSettings(JsonReader& r, FrictionSettings& f);
// The frame settings of a "settings" object: frame_mode (the old "frame" still read),
// world_axis, fallback_axis, sliding_speed (the old "auto_frame_speed" still read).
void parseFrameSettings(JsonReader& r, FrameSettings& f);
// Parses the "materials" table (named surfaces), before the bodies that refer to it.
void parseMaterials(JsonReader& root, SceneDesc& scene);
// A "surface" object (normal map file or generator, gain, texture size and rotation, mask, base
// colour); files resolve against base_dir and must exist. Also read by the engines' surfaces
// files (asperity/engines/engine_surfaces.hpp).
Surface parseSurface(JsonReader r, const std::string& base_dir);
// The JSON of a surface entry less its "mechanical" key (a preset name or {"E", "nu", "H",
// "tau"}), read into `mechanical`; `rest` holds the copy the returned reader reads.
JsonReader withoutMechanical(JsonReader& r, std::optional<Mechanical>& mechanical,
                             nlohmann::json& rest);
// Parses the "bodies" array (shapes, surfaces, OBJ meshes), checking names are unique.
void parseBodies(JsonReader& root, SceneDesc& scene);
// Writes one body back (with its meshes from scene.meshes).
nlohmann::json bodyToJson(const SceneDesc& scene, size_t index);

}  // namespace asperity::scene
