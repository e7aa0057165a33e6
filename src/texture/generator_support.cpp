// Seeded random numbers and strict parameter parsing for the generators.
#include "texture/generator_support.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "asperity/error.hpp"
#include "asperity/math/types.hpp"
#include "asperity/texture/png_io.hpp"
#include "texture/height_field.hpp"

namespace asperity::texgen {

namespace {

// Shortest readable form of a bound for messages ("0", "0.1", "8192").
std::string formatNumber(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// Parses the whole string as a finite number; false for anything else.
bool parseNumber(const std::string& text, double& value) {
  const char* first = text.data();
  const char* last = first + text.size();
  const auto [end, ec] = std::from_chars(first, last, value);
  return !text.empty() && ec == std::errc() && end == last && std::isfinite(value);
}

}  // namespace

double Rng::uniform() {
  // (k + 1) / 2^53 with k a 53-bit integer: never 0, so log() below is finite.
  return static_cast<double>((engine_() >> 11) + 1) * 0x1.0p-53;
}

double Rng::gaussian() {
  // Box-Muller: two uniforms give two independent standard normals; the second is kept.
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double radius = std::sqrt(-2.0 * std::log(uniform()));
  const double angle = 2.0 * kPi * uniform();
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

GeneratorContext::GeneratorContext(const GeneratorInfo& info, const GeneratorSpec& spec)
    : info_(info), spec_(spec), size_(spec.size), seed_(spec.seed) {
  // The map size.
  if (spec.size < 1 || spec.size > kMaxTextureSize) {
    fail("size must be in [1, " + std::to_string(kMaxTextureSize) + "], got " +
         std::to_string(spec.size));
  }
  // Every given parameter must be declared; numbers are checked now, before any work.
  for (const auto& [name, value] : spec.params) {
    const GeneratorParam& param = declared(name);
    if (param.kind == "number" && param.name == "axis") {
      axisRadians(name);
    } else if (param.kind == "number") {
      number(name);
    }
  }
}

const GeneratorParam& GeneratorContext::declared(const std::string& name) const {
  for (const GeneratorParam& p : info_.params) {
    if (p.name == name) {
      return p;
    }
  }
  std::string known;
  for (const GeneratorParam& p : info_.params) {
    known += (known.empty() ? "" : ", ") + p.name;
  }
  fail("unknown parameter '" + name + "' (known: " + (known.empty() ? "none" : known) + ")");
}

std::string GeneratorContext::raw(const GeneratorParam& param) const {
  const auto it = spec_.params.find(param.name);
  return it == spec_.params.end() ? param.default_value : it->second;
}

double GeneratorContext::number(const std::string& name) const {
  const GeneratorParam& param = declared(name);
  const std::string text = raw(param);
  double value = 0.0;
  if (!parseNumber(text, value) || value < param.min || value > param.max) {
    fail("parameter '" + name + "' must be a number in [" + formatNumber(param.min) + ", " +
         formatNumber(param.max) + "], got '" + text + "'");
  }
  return value;
}

int GeneratorContext::integer(const std::string& name) const {
  const double value = number(name);
  if (value != std::floor(value)) {
    const GeneratorParam& param = declared(name);
    fail("parameter '" + name + "' must be a whole number in [" + formatNumber(param.min) + ", " +
         formatNumber(param.max) + "], got '" + raw(param) + "'");
  }
  return static_cast<int>(value);
}

double GeneratorContext::axisRadians(const std::string& name) const {
  // "u" and "v" name the texture axes; anything else is an angle in degrees.
  const std::string text = raw(declared(name));
  if (text == "u") {
    return 0.0;
  }
  if (text == "v") {
    return 0.5 * kPi;
  }
  double degrees = 0.0;
  if (!parseNumber(text, degrees) || std::abs(degrees) > 360.0) {
    fail("parameter '" + name + "' must be 'u', 'v' or a number of degrees in [-360, 360], got '" +
         text + "'");
  }
  return degrees * kPi / 180.0;
}

std::string GeneratorContext::path(const std::string& name) const {
  const std::string text = raw(declared(name));
  if (text.empty()) {
    fail("parameter '" + name + "' is required");
  }
  return text;
}

void GeneratorContext::fail(const std::string& what) const {
  throw Error("texture generator '" + info_.name + "': " + what);
}

GeneratorParam numberParam(std::string name, double default_value, double min, double max,
                           std::string doc) {
  return {std::move(name), "number", formatNumber(default_value), min, max, std::move(doc)};
}

GeneratorParam axisParam(std::string default_value, std::string doc) {
  return {"axis", "number", std::move(default_value),
          -360.0, 360.0,    std::move(doc) + " ('u' = 0, 'v' = 90, or degrees from +u toward +v)"};
}

GeneratorEntry heightEntry(GeneratorInfo info,
                           std::function<Field(const GeneratorContext&)> heights) {
  auto make = [heights](const GeneratorContext& ctx) {
    return normalsFromHeights(heights(ctx), 1.0, Edge::Wrap);
  };
  return {std::move(info), std::move(make), std::move(heights)};
}

GeneratorParam pathParam(std::string name, std::string doc) {
  return {std::move(name), "path", "", 0.0, 0.0, std::move(doc)};
}

}  // namespace asperity::texgen
