// JsonReader: type and range checks over parsed JSON, with errors that name the JSON pointer.
#include "scene/json_reader.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "asperity/error.hpp"

namespace asperity::scene {

namespace {

// RFC 6901: "~" -> "~0", "/" -> "~1".
std::string escapePointerToken(const std::string& token) {
  std::string out;
  for (char c : token) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string bound(double x) {
  return x >= 1e300 ? "inf" : x <= -1e300 ? "-inf" : formatNumber(x);
}

// 1-based line and column of the byte before `byte` (nlohmann counts the last read byte from 1).
std::pair<size_t, size_t> lineColumn(const std::string& text, size_t byte) {
  const size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
  size_t line = 1;
  size_t line_start = 0;
  for (size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return {line, end - line_start + 1};
}

// Follows the parser's events to know the JSON pointer of each key, and refuses a key that an
// object already has (the parser would silently keep the last one).
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(std::string file) : file_(std::move(file)) {}

  bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& /*v*/) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        frames_.push_back({event == Event::object_start, {}, {}, 0});
        break;
      case Event::key:
        // The parser hands the key over as the parsed value; read it from the frame instead.
        break;
      case Event::object_end:
      case Event::array_end:
        frames_.pop_back();
        advance();
        break;
      case Event::value:
        advance();
        break;
    }
    return true;
  }

  void key(const std::string& name) {
    Frame& top = frames_.back();
    if (!top.keys.insert(name).second)
      throw Error(file_ + ": " + pointer() + "/" + escapePointerToken(name) + ": duplicate key");
    top.current_key = name;
  }

 private:
  struct Frame {
    bool is_object;
    std::set<std::string> keys;
    std::string current_key;
    size_t index;
  };
  // A finished element moves its array on to the next index.
  void advance() {
    if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
  }
  std::string pointer() const {
    std::string out;
    for (size_t i = 0; i + 1 < frames_.size(); ++i)
      out += "/" + (frames_[i].is_object ? escapePointerToken(frames_[i].current_key)
                                         : std::to_string(frames_[i].index));
    return out;
  }

  std::string file_;
  std::vector<Frame> frames_;
};

}  // namespace

bool Range::contains(double x) const {
  if (!std::isfinite(x)) return false;
  const bool above = min_open ? x > min : x >= min;
  const bool below = max_open ? x < max : x <= max;
  return above && below;
}

// Caps of 1e6 and more on a range from 0 are sanity limits: the words leave them out.
bool Range::softMax() const {
  return min == 0.0 && max >= 1e6 && max < 1e300;
}

std::string Range::describe() const {
  const bool no_min = min <= -1e300;
  const bool no_max = max >= 1e300;
  // The common shapes read as words.
  if (no_min && no_max) return "a finite number";
  if (min == 0.0 && (no_max || softMax()))
    return min_open ? "a positive number" : "a non-negative number";
  return std::string("a number in ") + (min_open ? "(" : "[") + bound(min) + ", " + bound(max) +
         (max_open ? ")" : "]");
}

nlohmann::json parseJsonText(const std::string& text, const std::string& file) {
  try {
    DuplicateKeyCheck check(file);
    return nlohmann::json::parse(text, [&](int depth, nlohmann::json::parse_event_t event,
                                           nlohmann::json& parsed) {
      using Event = nlohmann::json::parse_event_t;
      if (event == Event::key) check.key(parsed.get<std::string>());
      // A container opened at `depth` nests depth + 1 deep; deeper documents are refused
      // before they are built (recursive walks over them would overflow the stack).
      if ((event == Event::object_start || event == Event::array_start) &&
          depth + 1 > kMaxJsonDepth)
        throw Error(file + ": JSON nested " + std::to_string(depth + 1) +
                    " levels deep, more than the " + std::to_string(kMaxJsonDepth) + " allowed");
      return check(depth, event, parsed);
    });
  } catch (const nlohmann::json::parse_error& e) {
    // Keep nlohmann's explanation, drop its "[json.exception...] parse error at ..." prefix.
    std::string what = e.what();
    const size_t column = what.find("column ");
    const size_t colon = column == std::string::npos ? what.find(": ") : what.find(": ", column);
    if (colon != std::string::npos) what = what.substr(colon + 2);
    const auto [line, col] = lineColumn(text, e.byte);
    throw Error(file + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + what);
  } catch (const nlohmann::json::out_of_range& e) {
    // "number overflow parsing '1e999'": locate the literal for its line and column.
    std::string what = e.what();
    what = what.substr(what.find("] ") + 2);
    const size_t quote = what.find('\'');
    const size_t at = quote == std::string::npos
                          ? std::string::npos
                          : text.find(what.substr(quote + 1, what.size() - quote - 2));
    if (at == std::string::npos) throw Error(file + ": " + what);
    const auto [line, col] = lineColumn(text, at + 1);
    throw Error(file + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + what);
  }
}

nlohmann::json parseJsonFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseJsonText(text.str(), path);
}

std::string describeValue(const nlohmann::json& value) {
  // Numbers print as themselves; other values with their type so "1" and 1 differ.
  if (value.is_number()) return formatNumber(value.get<double>());
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(value.type_name()) + " " + text;
}

JsonReader::JsonReader(const nlohmann::json& value, std::string file, std::string pointer)
    : value_(value), file_(std::move(file)), pointer_(std::move(pointer)) {}

std::string JsonReader::childPointer(const std::string& key) const {
  return pointer_ + "/" + escapePointerToken(key);
}

std::string JsonReader::childPointer(size_t index) const {
  return pointer_ + "/" + std::to_string(index);
}

void JsonReader::fail(const std::string& what) const {
  throw Error(file_ + ": " + (pointer_.empty() ? "/" : pointer_) + ": " + what);
}

void JsonReader::failAt(const std::string& key, const std::string& what) const {
  throw Error(file_ + ": " + childPointer(key) + ": " + what);
}

void JsonReader::warnAt(const std::string& key, const std::string& what) const {
  if (warnings_) warnings_->push_back(file_ + ": " + childPointer(key) + ": " + what);
}

std::string JsonReader::renamed(const std::string& current, const std::string& deprecated) {
  // The old name is looked at without marking it known, so finish() lists only the new one.
  requireObject();
  known_.insert(current);
  if (!value_.contains(deprecated)) return current;
  if (has(current))
    failAt(deprecated, "deprecated name of \"" + current + "\", which is also given: keep only \"" +
                           current + "\"");
  known_.insert(deprecated);
  warnAt(deprecated, "deprecated, use \"" + current + "\"");
  return deprecated;
}

void JsonReader::requireObject() const {
  if (!value_.is_object()) fail("must be an object, got " + describeValue(value_));
}

double JsonReader::asNumber(Range range) const {
  if (!value_.is_number() || !range.contains(value_.get<double>())) {
    // Over a sanity limit that the range's words leave out: say so.
    if (value_.is_number() && range.softMax() && value_.get<double>() > range.max)
      fail("must be at most " + bound(range.max) + ", got " + describeValue(value_));
    fail("must be " + range.describe() + ", got " + describeValue(value_));
  }
  return value_.get<double>();
}

const nlohmann::json* JsonReader::member(const std::string& key) {
  requireObject();
  known_.insert(key);
  const auto it = value_.find(key);
  return it == value_.end() ? nullptr : &*it;
}

bool JsonReader::has(const std::string& key) {
  return member(key) != nullptr;
}

double JsonReader::number(const std::string& key, double fallback, Range range) {
  const nlohmann::json* v = member(key);
  if (v == nullptr) return fallback;
  return JsonReader(*v, file_, childPointer(key)).asNumber(range);
}

double JsonReader::requiredNumber(const std::string& key, Range range) {
  if (!has(key)) fail("missing key \"" + key + "\" (" + range.describe() + ")");
  return number(key, 0.0, range);
}

int JsonReader::integer(const std::string& key, int fallback, int min, int max) {
  const nlohmann::json* v = member(key);
  if (v == nullptr) return fallback;
  // Integers only: 4.0 and 4.5 are both refused, so a saved scene reads back the same.
  if (!v->is_number_integer() || v->get<double>() < min || v->get<double>() > max)
    failAt(key, "must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                    "], got " + describeValue(*v));
  return static_cast<int>(v->get<int64_t>());
}

uint64_t JsonReader::unsignedInteger(const std::string& key, uint64_t fallback) {
  const nlohmann::json* v = member(key);
  if (v == nullptr) return fallback;
  // A non-negative signed integer is one too (JSON built in code, rather than parsed, holds 3
  // as signed).
  if (!v->is_number_unsigned() && !(v->is_number_integer() && v->get<int64_t>() >= 0))
    failAt(key, "must be a non-negative integer, got " + describeValue(*v));
  return v->get<uint64_t>();
}

bool JsonReader::boolean(const std::string& key, bool fallback) {
  const nlohmann::json* v = member(key);
  if (v == nullptr) return fallback;
  if (!v->is_boolean()) failAt(key, "must be true or false, got " + describeValue(*v));
  return v->get<bool>();
}

std::string JsonReader::string(const std::string& key, const std::string& fallback) {
  const nlohmann::json* v = member(key);
  if (v == nullptr) return fallback;
  if (!v->is_string()) failAt(key, "must be a string, got " + describeValue(*v));
  return v->get<std::string>();
}

std::string JsonReader::requiredString(const std::string& key) {
  if (!has(key)) fail("missing key \"" + key + "\" (a string)");
  return string(key, {});
}

Vec3 JsonReader::asVec3(Range range) const {
  if (!value_.is_array() || value_.size() != 3)
    fail("must be an array of 3 numbers, got " + describeValue(value_));
  // Each component is checked at its own pointer (".../half_extents/1").
  Vec3 out;
  for (size_t i = 0; i < 3; ++i)
    out[static_cast<Eigen::Index>(i)] =
        JsonReader(value_[i], file_, childPointer(i)).asNumber(range);
  return out;
}

Vec3 JsonReader::vec3(const std::string& key, const Vec3& fallback, Range range) {
  const nlohmann::json* v = member(key);
  if (v == nullptr) return fallback;
  return JsonReader(*v, file_, childPointer(key)).asVec3(range);
}

Vec3 JsonReader::requiredVec3(const std::string& key, Range range) {
  if (!has(key)) fail("missing key \"" + key + "\" (an array of 3 numbers)");
  return vec3(key, Vec3::Zero(), range);
}

Vec3 JsonReader::direction(const std::string& key, const Vec3& fallback) {
  if (!has(key)) return fallback;
  const Vec3 v = vec3(key, fallback);
  const double n = v.norm();
  if (!(n > 1e-12) || !std::isfinite(n))
    failAt(key, "must be a non-zero vector, got [" + formatNumber(v.x()) + ", " +
                    formatNumber(v.y()) + ", " + formatNumber(v.z()) + "]");
  // A unit vector is kept bit for bit, so saving and reloading changes nothing.
  return std::abs(n - 1.0) > 1e-12 ? Vec3(v / n) : v;
}

Quat JsonReader::quaternion(const std::string& key, const Quat& fallback) {
  const nlohmann::json* v = member(key);
  if (v == nullptr) return fallback;
  if (!v->is_array() || v->size() != 4)
    failAt(key, "must be a quaternion [w, x, y, z], got " + describeValue(*v));
  double c[4];
  for (size_t i = 0; i < 4; ++i)
    c[i] = JsonReader((*v)[i], file_, childPointer(key) + "/" + std::to_string(i))
               .asNumber(Range::any());
  Quat q(c[0], c[1], c[2], c[3]);
  const double n = q.norm();
  if (!(n > 1e-9) || !std::isfinite(n))
    failAt(key, "must be a non-zero quaternion [w, x, y, z], got " + v->dump());
  // A unit quaternion is kept bit for bit, so saving and reloading changes nothing.
  if (std::abs(n - 1.0) > 1e-12) q.normalize();
  return q;
}

JsonReader JsonReader::object(const std::string& key) {
  static const nlohmann::json kEmpty = nlohmann::json::object();
  const nlohmann::json* v = member(key);
  JsonReader child(v ? *v : kEmpty, file_, childPointer(key));
  child.warnings_ = warnings_;
  child.requireObject();
  return child;
}

std::vector<JsonReader> JsonReader::elements(const std::string& key) {
  std::vector<JsonReader> out;
  const nlohmann::json* v = member(key);
  if (v == nullptr) return out;
  if (!v->is_array()) failAt(key, "must be an array, got " + describeValue(*v));
  for (size_t i = 0; i < v->size(); ++i) {
    out.emplace_back((*v)[i], file_, childPointer(key) + "/" + std::to_string(i));
    out.back().warnings_ = warnings_;
  }
  return out;
}

std::vector<JsonReader> JsonReader::objects(const std::string& key) {
  std::vector<JsonReader> out = elements(key);
  for (const JsonReader& r : out) r.requireObject();
  return out;
}

std::string oneOf(const std::vector<std::string>& names) {
  std::string out = "one of ";
  for (size_t i = 0; i < names.size(); ++i) out += (i ? ", \"" : "\"") + names[i] + "\"";
  return out;
}

void JsonReader::finish() const {
  requireObject();
  for (const auto& [key, v] : value_.items()) {
    if (known_.count(key)) continue;
    std::string expected;
    for (const std::string& k : known_) expected += (expected.empty() ? "" : ", ") + k;
    failAt(key, "unknown key (expected one of: " + expected + ")");
  }
}

}  // namespace asperity::scene
