// Measurements of a material pair for calibration (calibrate.hpp): CSV of angle_deg,mu, of tilt
// angles, or of slides of a launched block, each row turned into a coefficient.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/tribometer/calibrate.hpp"
#include "math/number_text.hpp"

namespace asperity {

namespace {

// The line without spaces around it.
std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  const size_t e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// A line's comma-separated cells, trimmed.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

// The kind a header names; throws naming the line otherwise.
MeasurementKind headerKind(const std::string& header, const std::string& where) {
  std::string h;
  for (const std::string& c : cells(header)) h += (h.empty() ? "" : ",") + c;
  if (h == "angle_deg,mu") return MeasurementKind::Mu;
  if (h == "angle_deg,tilt_deg") return MeasurementKind::TiltAngle;
  if (h == "angle_deg,speed,distance") return MeasurementKind::SlideDistance;
  throw Error(where +
              ": expected the header angle_deg,mu or angle_deg,tilt_deg or "
              "angle_deg,speed,distance, got '" +
              header + "'");
}

// A cell as a finite number; throws `where: NAME must be a number, got 'x'`.
double number(const std::string& cell, const char* name, const std::string& where) {
  char* end = nullptr;
  const double x = std::strtod(cell.c_str(), &end);
  if (cell.empty() || end != cell.c_str() + cell.size() || !std::isfinite(x))
    throw Error(where + ": " + name + " must be a finite number, got '" + cell + "'");
  return x;
}

// The largest coefficient a row may give: the scenes' mu0 bound. A fit to rows far past it
// (1e300, a typo or a forged file) would give gains of 0 and a residual of infinity.
constexpr double kMaxMeasuredMu = 100.0;

// One data row's coefficient by kind, its values checked.
double measuredMu(MeasurementKind kind, const std::vector<std::string>& c, double gravity,
                  const std::string& where) {
  if (kind == MeasurementKind::Mu) {
    const double mu = number(c[1], "mu", where);
    if (mu < 0.0) throw Error(where + ": mu must be >= 0, got " + c[1]);
    return mu;
  }
  if (kind == MeasurementKind::TiltAngle) {
    const double tilt = number(c[1], "tilt_deg", where);
    if (tilt < 0.0 || tilt >= 90.0)
      throw Error(where + ": tilt_deg must be in [0, 90), got " + c[1]);
    return std::tan(tilt * kPi / 180.0);
  }
  const double speed = number(c[1], "speed", where);
  const double distance = number(c[2], "distance", where);
  if (!(speed > 0.0)) throw Error(where + ": speed must be > 0, got " + c[1]);
  if (!(distance > 0.0)) throw Error(where + ": distance must be > 0, got " + c[2]);
  return speed * speed / (2.0 * gravity * distance);
}

double rowMu(MeasurementKind kind, const std::vector<std::string>& c, double gravity,
             const std::string& where) {
  const double mu = measuredMu(kind, c, gravity, where);
  if (!(mu <= kMaxMeasuredMu)) {
    throw Error(where + ": the row gives mu = " + formatNumber(mu) + ", more than " +
                formatNumber(kMaxMeasuredMu) + " (no measured pair grips so)");
  }
  return mu;
}

}  // namespace

Measurements parseMeasurements(const std::string& text, const std::string& file, double gravity) {
  Measurements data;
  data.file = file;
  std::stringstream in(text);
  std::string line;
  bool header = false;
  for (int n = 1; std::getline(in, line); ++n) {
    // Comments and blank lines, then the header, then rows of as many cells.
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::string where = file + ":" + std::to_string(n);
    if (!header) {
      data.kind = headerKind(t, where);
      header = true;
      continue;
    }
    const std::vector<std::string> c = cells(t);
    const size_t expected = data.kind == MeasurementKind::SlideDistance ? 3 : 2;
    if (c.size() != expected)
      throw Error(where + ": expected " + std::to_string(expected) + " values, got " +
                  std::to_string(c.size()));
    data.rows.push_back({n, number(c[0], "angle_deg", where), rowMu(data.kind, c, gravity, where)});
  }
  if (data.rows.empty()) throw Error(file + ": no measurements (a header, then one row per line)");
  return data;
}

Measurements readMeasurements(const std::string& path, double gravity) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open (missing or unreadable)");
  std::stringstream text;
  text << in.rdbuf();
  return parseMeasurements(text.str(), path, gravity);
}

}  // namespace asperity
