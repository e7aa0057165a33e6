// Helpers shared by the tribometer tests: surfaces by text, and quick settings.
#pragma once

#include <string>

#include "asperity/tribometer/tribometer.hpp"

namespace asperity::test {

// Block (A) and plate (B) from texture texts (`flat` for no normal map), with their gains and
// `texture_size` metres per repeat.
inline TribometerSurfaces tribometerPair(const std::string& block, const std::string& plate,
                                         double k_a = 1.0, double k_b = 1.0,
                                         double texture_size = 0.256) {
  Diagnostics diagnostics;
  TribometerSurfaces s;
  s.block.gain = k_a;
  if (block != "flat") s.block = tribometerSurface(block, k_a, texture_size, diagnostics);
  s.plate.gain = k_b;
  if (plate != "flat") s.plate = tribometerSurface(plate, k_b, texture_size, diagnostics);
  return s;
}

// The drag test alone in `directions` directions, with nominal coefficient `mu0`.
inline TribometerSettings dragOnly(int directions, double mu0) {
  TribometerSettings settings;
  settings.directions = directions;
  settings.tilt = false;
  settings.friction.mu0 = mu0;
  return settings;
}

}  // namespace asperity::test
