// Height fields: noise, blurs, rotation and central-difference normals for the generators.
#include "texture/height_field.hpp"

#include <algorithm>
#include <cmath>

namespace asperity::texgen {

namespace {

// One box-blur pass of radius r over `count` samples spaced `stride` apart, wrapping.
void blurLine(double* data, int count, size_t stride, int r, std::vector<double>& scratch) {
  scratch.resize(static_cast<size_t>(count));
  for (int k = 0; k < count; ++k) {
    scratch[k] = data[static_cast<size_t>(k) * stride];
  }
  // Running sum over the window [k - r, k + r].
  double sum = 0.0;
  for (int d = -r; d <= r; ++d) {
    sum += scratch[wrapTexel(d, count)];
  }
  const double norm = 1.0 / (2 * r + 1);
  for (int k = 0; k < count; ++k) {
    data[static_cast<size_t>(k) * stride] = sum * norm;
    sum += scratch[wrapTexel(k + r + 1, count)] - scratch[wrapTexel(k - r, count)];
  }
}

}  // namespace

Field::Field(int w, int h, double fill)
    : width(w), height(h), values(static_cast<size_t>(w) * static_cast<size_t>(h), fill) {}

double Field::get(int i, int j, Edge edge) const {
  if (edge == Edge::Wrap) {
    return at(wrapTexel(i, width), wrapTexel(j, height));
  }
  return at(std::clamp(i, 0, width - 1), std::clamp(j, 0, height - 1));
}

double Field::sampleWrapped(double x, double y) const {
  return bilinearWrapped(x, y, width, height, [this](int i, int j) { return at(i, j); });
}

Field whiteNoise(int width, int height, Rng& rng) {
  Field f(width, height);
  for (double& v : f.values) {
    v = rng.gaussian();
  }
  return f;
}

void boxBlur(Field& field, int rx, int ry, int passes) {
  std::vector<double> scratch;
  for (int pass = 0; pass < passes; ++pass) {
    // Along i, row by row.
    for (int j = 0; rx > 0 && j < field.height; ++j) {
      blurLine(&field.at(0, j), field.width, 1, rx, scratch);
    }
    // Along j, column by column.
    for (int i = 0; ry > 0 && i < field.width; ++i) {
      blurLine(&field.at(i, 0), field.height, static_cast<size_t>(field.width), ry, scratch);
    }
  }
}

void standardise(Field& field) {
  const auto n = static_cast<double>(field.values.size());
  double mean = 0.0;
  for (double v : field.values) mean += v;
  mean /= n;
  double var = 0.0;
  for (double v : field.values) var += (v - mean) * (v - mean);
  const double sd = std::sqrt(var / n);
  for (double& v : field.values) {
    v = sd > 0.0 ? (v - mean) / sd : 0.0;
  }
}

Field rotated(const Field& field, double radians) {
  // Output texel centre p reads the input at R(-a) p.
  const double c = std::cos(radians);
  const double s = std::sin(radians);
  const auto snap = [](double x) {
    const double r = std::round(x);
    return std::abs(x - r) < 1e-9 ? r : x;  // exact texels for multiples of 90 degrees
  };
  Field out(field.width, field.height);
  for (int j = 0; j < field.height; ++j) {
    for (int i = 0; i < field.width; ++i) {
      const double x = i + 0.5;
      const double y = j + 0.5;
      out.at(i, j) = field.sampleWrapped(snap(c * x + s * y - 0.5), snap(-s * x + c * y - 0.5));
    }
  }
  return out;
}

double slopeU(const Field& h, int i, int j, Edge edge) {
  if (edge == Edge::Clamp && (i == 0 || i == h.width - 1)) {
    // One-sided difference at the picture's border.
    return h.width < 2 ? 0.0 : (i == 0 ? h.at(1, j) - h.at(0, j) : h.at(i, j) - h.at(i - 1, j));
  }
  return 0.5 * (h.get(i + 1, j, edge) - h.get(i - 1, j, edge));
}

double slopeV(const Field& h, int i, int j, Edge edge) {
  if (edge == Edge::Clamp && (j == 0 || j == h.height - 1)) {
    return h.height < 2 ? 0.0 : (j == 0 ? h.at(i, 1) - h.at(i, 0) : h.at(i, j) - h.at(i, j - 1));
  }
  return 0.5 * (h.get(i, j + 1, edge) - h.get(i, j - 1, edge));
}

double rmsSlope(const Field& h, Edge edge) {
  double sum = 0.0;
  for (int j = 0; j < h.height; ++j) {
    for (int i = 0; i < h.width; ++i) {
      const double gu = slopeU(h, i, j, edge);
      const double gv = slopeV(h, i, j, edge);
      sum += gu * gu + gv * gv;
    }
  }
  return std::sqrt(sum / static_cast<double>(h.values.size()));
}

void scaleToRmsSlope(Field& h, double target, Edge edge) {
  const double current = rmsSlope(h, edge);
  const double factor = current > 0.0 ? target / current : 0.0;
  for (double& v : h.values) {
    v *= factor;
  }
}

NormalMap normalsFromHeights(const Field& h, double scale, Edge edge) {
  NormalMap map(h.width, h.height);
  for (int j = 0; j < h.height; ++j) {
    for (int i = 0; i < h.width; ++i) {
      // m = normalize(-dh/du, -dh/dv, 1).
      const double gu = scale * slopeU(h, i, j, edge);
      const double gv = scale * slopeV(h, i, j, edge);
      const double inv = 1.0 / std::sqrt(gu * gu + gv * gv + 1.0);
      map.at(i, j) = Vec3f(static_cast<float>(-gu * inv), static_cast<float>(-gv * inv),
                           static_cast<float>(inv));
    }
  }
  return map;
}

}  // namespace asperity::texgen
