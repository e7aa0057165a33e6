// A periodic, piecewise-constant slope profile along one axis (sawtooth, thread, tool marks).
// Its integral, height(), need not return to zero over a period: a normal map may hold facets
// that no height field has (the paper's sawtooth, Fig. 8), and the box filter still works.
#pragma once

#include <vector>

namespace asperity::texgen {

class PeriodicProfile {
 public:
  // One linear piece: its width (texels) and slope (height per texel).
  struct Piece {
    double width = 0.0;
    double slope = 0.0;
  };

  explicit PeriodicProfile(std::vector<Piece> pieces);

  double period() const { return period_; }
  // Integral of the slope from 0 to x (texels).
  double height(double x) const;
  // Mean slope over the window [x - w/2, x + w/2]; w = 0 gives the slope at x itself.
  double slope(double x, double window = 0.0) const;

 private:
  std::vector<Piece> pieces_;
  std::vector<double> starts_;   // x where each piece starts, within one period
  std::vector<double> heights_;  // height where each piece starts
  double period_ = 0.0;
  double rise_ = 0.0;  // integral over one period
};

}  // namespace asperity::texgen
