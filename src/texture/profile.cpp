// Periodic piecewise-linear height profiles.
#include "texture/profile.hpp"

#include <cmath>

namespace asperity::texgen {

PeriodicProfile::PeriodicProfile(std::vector<Piece> pieces) : pieces_(std::move(pieces)) {
  // Prefix sums of widths and heights.
  double x = 0.0;
  double h = 0.0;
  for (const Piece& p : pieces_) {
    starts_.push_back(x);
    heights_.push_back(h);
    x += p.width;
    h += p.width * p.slope;
  }
  period_ = x;
  rise_ = h;
}

double PeriodicProfile::height(double x) const {
  // Reduce to one period, then find the piece (profiles have a handful of pieces).
  const double turns = std::floor(x / period_);
  const double t = x - turns * period_;
  for (size_t k = pieces_.size(); k-- > 0;) {
    if (t >= starts_[k]) {
      return turns * rise_ + heights_[k] + (t - starts_[k]) * pieces_[k].slope;
    }
  }
  return turns * rise_;
}

double PeriodicProfile::slope(double x, double window) const {
  // Box-filtered slope: (H(x + w/2) - H(x - w/2)) / w with H the integral of the slope.
  if (window > 0.0) {
    return (height(x + 0.5 * window) - height(x - 0.5 * window)) / window;
  }
  const double t = x - std::floor(x / period_) * period_;
  for (size_t k = pieces_.size(); k-- > 0;) {
    if (t >= starts_[k]) {
      return pieces_[k].slope;
    }
  }
  return pieces_.front().slope;
}

}  // namespace asperity::texgen
