// The real area of contact between two rough surfaces (SPEC 13): the Greenwood and Williamson
// model over the summits of the composite height map, elastic (Hertz) up to the load at which a
// summit's mean pressure reaches the hardness H and plastic (pressure H) beyond, with the mean
// separation solved by bisection so that the summits carry the load. docs/contact-area.md.
#pragma once

#include <string>
#include <vector>

#include "asperity/texture/height_map.hpp"

namespace asperity {

// One summit of the composite surface: a texel higher than its eight neighbours.
struct Summit {
  double height = 0.0;  // metres
  double radius = 0.0;  // curvature radius (metres): 1 / mean of -h_uu and -h_vv
  int i = 0;            // texel
  int j = 0;
};

// The summits of a composite surface and what the model needs of them.
struct SummitSet {
  std::vector<Summit> summits;  // highest first
  double apparent_area = 0.0;   // A_0 (m^2): the patch the heights cover
  double texel = 0.0;           // texel width (m)
  int width = 0;
  int height = 0;
  double sigma = 0.0;  // standard deviation of summit heights (m)
  double beta = 0.0;   // mean summit curvature radius (m)
  bool flat = false;   // no relief at all: any load gives full contact
  HeightMap surface;   // the composite heights, mean zero
};

// The composite roughness of B and A pressed together (heights add; A is resampled onto B's
// grid when its size differs; null A = a flat, smooth partner) over a square patch of
// texture_size metres, and its summits. Throws asperity::Error for an empty map or a
// texture_size that is not positive.
SummitSet findSummits(const HeightMap& b, const HeightMap* a, double texture_size);

// The same for heights already summed (`composite`, any mean), into `set`, whose buffers are
// reused: nothing is allocated once they are large enough, as a per-contact model needs.
void findSummitsInto(const HeightMap& composite, double texture_size, SummitSet& set);

struct ContactMaterial {
  double modulus = 0.0;   // E* (Pa), the pair's effective modulus
  double hardness = 0.0;  // H (Pa); 0 = no plastic limit
};

struct ContactArea {
  double load = 0.0;              // W (N)
  double real_area = 0.0;         // A_r (m^2), at most apparent_area
  double apparent_area = 0.0;     // A_0 (m^2)
  double fraction = 0.0;          // A_r / A_0
  double mean_pressure = 0.0;     // W / A_r (Pa)
  double plasticity_index = 0.0;  // (E* / H) sqrt(sigma / beta); 0 when no H is given
  double separation = 0.0;        // d: the partner's plane above the mean composite height (m)
  int summits_in_contact = 0;
  int summits_plastic = 0;  // touching summits past the onset of plastic flow, R (H / E*)^2
  int summits = 0;
};

// A_r under `load` newtons. Throws asperity::Error for a load < 0 or a modulus or hardness
// that is not a finite positive number (hardness may be 0: none).
ContactArea solveContact(const SummitSet& set, const ContactMaterial& material, double load);

// Which texels are in contact at `result` (each touching summit as a disc of its contact
// radius sqrt(R delta)), rows bottom-up like HeightMap; 1 = contact.
std::vector<unsigned char> contactMask(const SummitSet& set, const ContactArea& result);
// The same into `mask` (resized; no allocation once large enough).
void contactMaskInto(const SummitSet& set, const ContactArea& result,
                     std::vector<unsigned char>& mask);

// An 8-bit grey PNG of the contact maps of `results` side by side, one panel per result with a
// black gap of four texels: the composite heights in dark greys, the texels in contact white.
// Throws asperity::Error naming the file if it cannot be written.
void saveContactMapPng(const SummitSet& set, const std::vector<ContactArea>& results,
                       const std::string& path);

}  // namespace asperity
