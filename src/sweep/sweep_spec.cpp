// Variations of a sweep: "PATH=SPEC" parsing, `*` path expansion and the seeded draws.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "asperity/error.hpp"
#include "asperity/sweep/sweep.hpp"

namespace asperity {
namespace {

// A variation rejected: `subject` is the variation as written.
[[noreturn]] void badVariation(const std::string& subject, const std::string& problem) {
  throw SweepError(SweepField::Vary, subject, problem);
}

// A finite number filling all of `text` (spaces around it allowed), else throws.
double parseNumber(std::string_view text, const std::string& what) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  double value = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() ||
      !std::isfinite(value))
    badVariation(what, "'" + std::string(text) + "' is not a finite number");
  return value;
}

// Checks the argument count and ranges of each distribution.
void checkArgs(const Variation& v, const std::string& what) {
  const size_t n = v.args.size();
  switch (v.distribution) {
    case Distribution::Uniform:
      if (n != 2) badVariation(what, "uniform(a,b) takes 2 numbers");
      if (!(v.args[0] <= v.args[1])) badVariation(what, "uniform(a,b) needs a <= b");
      break;
    case Distribution::Normal:
      if (n != 2) badVariation(what, "normal(mean,sd) takes 2 numbers");
      if (v.args[1] < 0.0) badVariation(what, "normal(mean,sd) needs sd >= 0");
      break;
    case Distribution::Choice:
      if (n < 1) badVariation(what, "choice(v1,v2,...) takes at least one number");
      break;
    case Distribution::Grid:
      if (n != 3) badVariation(what, "grid(a,b,n) takes 3 numbers");
      if (v.args[2] < 1.0 || v.args[2] > 1e6 || v.args[2] != std::floor(v.args[2]))
        badVariation(what, "grid(a,b,n) needs a whole n in 1..1000000");
      break;
  }
}

// SplitMix64 finaliser: a well-mixed 64-bit value from any input.
uint64_t mix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Uniform in [0, 1) from the top 53 bits (exact doubles, the same on every platform).
double unit(uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

// The draw of one variation for one sample: its own stream keyed by (seed, sample, variation).
double draw(const Variation& v, uint64_t seed, int64_t sample, size_t variation) {
  const uint64_t key =
      mix64(mix64(seed) ^ mix64(static_cast<uint64_t>(sample) + 0x632be59bd9b4e019ull) ^
            mix64(variation * 0x8cb92ba72f3d8dd7ull + 1));
  const double u1 = unit(mix64(key)), u2 = unit(mix64(key + 1));
  switch (v.distribution) {
    case Distribution::Uniform:
      return v.args[0] + (v.args[1] - v.args[0]) * u1;
    case Distribution::Normal:
      // Box-Muller; 1 - u1 lies in (0, 1] so the logarithm is finite.
      return v.args[0] +
             v.args[1] * std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * kPi * u2);
    case Distribution::Choice:
      return v.args[std::min(static_cast<size_t>(u1 * static_cast<double>(v.args.size())),
                             v.args.size() - 1)];
    case Distribution::Grid:
      break;
  }
  return 0.0;
}

// The library's word for each field of a sweep's description.
const char* fieldWord(SweepField field) {
  switch (field) {
    case SweepField::Vary:
      return "variation";
    case SweepField::Measures:
      return "measure";
    case SweepField::Samples:
      return "samples";
    case SweepField::Seconds:
      return "seconds";
    case SweepField::Threads:
      return "threads";
  }
  return "sweep";
}

// "NAME SUBJECT: PROBLEM", without the subject when there is none.
std::string sweepMessage(const std::string& name, const std::string& subject,
                         const std::string& problem) {
  return name + (subject.empty() ? "" : " " + subject) + ": " + problem;
}

}  // namespace

SweepError::SweepError(SweepField field, std::string subject, std::string problem)
    : Error(sweepMessage(fieldWord(field), subject, problem)),
      field_(field),
      subject_(std::move(subject)),
      problem_(std::move(problem)) {}

std::string SweepError::messageNaming(const std::string& name) const {
  return sweepMessage(name, subject_, problem_);
}

Variation parseVariation(const std::string& path, const std::string& spec) {
  const std::string what = "'" + path + "=" + spec + "'";
  if (path.empty() || path.front() != '/')
    badVariation(what, "the path must be a JSON pointer starting with '/'");
  // NAME(ARGS) with NAME one of the four distributions.
  const size_t open = spec.find('(');
  if (open == std::string::npos || spec.back() != ')')
    badVariation(what, "expected uniform(a,b), normal(m,s), choice(a,b,...) or grid(a,b,n)");
  const std::string name = spec.substr(0, open);
  Variation v;
  v.path = path;
  if (name == "uniform")
    v.distribution = Distribution::Uniform;
  else if (name == "normal")
    v.distribution = Distribution::Normal;
  else if (name == "choice")
    v.distribution = Distribution::Choice;
  else if (name == "grid")
    v.distribution = Distribution::Grid;
  else
    badVariation(what,
                 "unknown distribution '" + name + "' (available: uniform, normal, choice, grid)");
  // Comma-separated numbers between the parentheses.
  const std::string_view args(spec.data() + open + 1, spec.size() - open - 2);
  size_t start = 0;
  while (start <= args.size() && !args.empty()) {
    const size_t comma = std::min(args.find(',', start), args.size());
    v.args.push_back(parseNumber(args.substr(start, comma - start), what));
    start = comma + 1;
  }
  checkArgs(v, what);
  return v;
}

Variation parseVariation(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos) badVariation("'" + text + "'", "expected PATH=SPEC");
  return parseVariation(text.substr(0, eq), text.substr(eq + 1));
}

std::vector<std::string> expandPath(const nlohmann::json& scene, const std::string& path) {
  const std::string& what = path;
  // Walk the segments, keeping every (pointer, node) pair that matches so far. Below a `*`,
  // elements without the rest of the path drop out (static bodies have no velocity); a
  // segment that no element has is an error.
  std::vector<std::pair<std::string, const nlohmann::json*>> matches = {{"", &scene}};
  bool under_star = false;
  size_t start = 1;
  while (start <= path.size()) {
    const size_t slash = std::min(path.find('/', start), path.size());
    const std::string segment = path.substr(start, slash - start);
    std::vector<std::pair<std::string, const nlohmann::json*>> next;
    std::string missing;
    for (const auto& [pointer, node] : matches) {
      if (segment == "*") {
        if (!node->is_array()) badVariation(what, pointer + " is not an array");
        for (size_t i = 0; i < node->size(); ++i)
          next.emplace_back(pointer + "/" + std::to_string(i), &(*node)[i]);
        continue;
      }
      const nlohmann::json::json_pointer one("/" + segment);
      if (node->is_primitive() || !node->contains(one)) {
        if (missing.empty()) missing = pointer + "/" + segment;
        if (!under_star) badVariation(what, missing + " is not in the scene");
        continue;
      }
      next.emplace_back(pointer + "/" + segment, &node->at(one));
    }
    if (next.empty())
      badVariation(what, (missing.empty() ? path : missing) + " is not in the scene");
    under_star = under_star || segment == "*";
    matches = std::move(next);
    start = slash + 1;
  }
  // Every match must be a number (the value replaces it).
  std::vector<std::string> pointers;
  for (const auto& [pointer, node] : matches) {
    if (!node->is_number())
      badVariation(what, pointer + " is " + node->type_name() + ", not a number");
    pointers.push_back(pointer);
  }
  return pointers;
}

std::vector<double> Sweep::values(int64_t index) const {
  std::vector<double> out;
  int64_t radix = 1;  // product of the earlier grids' sizes
  for (size_t j = 0; j < desc_.vary.size(); ++j) {
    const Variation& v = desc_.vary[j];
    if (v.distribution != Distribution::Grid) {
      out.push_back(draw(v, desc_.seed, index, j));
      continue;
    }
    // Grid: digit of the sample index in mixed radix, a + (b - a) k / (n - 1).
    const auto n = static_cast<int64_t>(v.args[2]);
    const int64_t k = (index / radix) % n;
    radix = radix > std::numeric_limits<int64_t>::max() / n ? radix : radix * n;
    out.push_back(n == 1 ? v.args[0]
                         : v.args[0] + (v.args[1] - v.args[0]) * static_cast<double>(k) /
                                           static_cast<double>(n - 1));
  }
  return out;
}

}  // namespace asperity
