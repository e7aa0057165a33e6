// The measuring helpers the experiments share (experiment_support.hpp).
#include "experiment_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace asperity::experiments {

PaperRow paperRow(double k_a, double k_b, double mu0, double w, double dt_ms, int contacts,
                  double total, double patch, double averaging) {
  return {k_a, k_b, mu0, w, dt_ms, contacts, total, patch, averaging};
}

double horizontalTravel(const std::vector<Transform>& poses) {
  const Vec3 d = poses.back().position - poses.front().position;
  return std::hypot(d.x(), d.y());
}

double tiltDegrees(const std::vector<Transform>& poses, size_t i) {
  const Vec3 z0 = poses.front().rotation * Vec3::UnitZ();
  const Vec3 zi = poses[i].rotation * Vec3::UnitZ();
  return std::acos(std::clamp(z0.dot(zi), -1.0, 1.0)) * 180.0 / kPi;
}

std::string num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.3g", x);
  return buffer;
}

std::string relation(bool holds, const char* op) {
  return holds ? std::string(" ") + op + " " : std::string(" NOT ") + op + " ";
}

}  // namespace asperity::experiments
