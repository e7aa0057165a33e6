// A path-tracking reader over parsed JSON for the scene loader. Every getter checks the value's
// type and range, and every error is one line `file: /json/pointer: what is wrong`, with the
// JSON pointer (RFC 6901) of the offending value. finish() rejects keys nobody asked for.
// Renamed keys are still read under their old name, with a warning (renamed()).
//
//   JsonReader r(json, "scenes/x.json");
//   double dt = r.number("dt", 0.01, Range::leftOpen(0.0, 1.0));
//   r.finish();  // "scenes/x.json: /dtt: unknown key (expected one of: dt, ...)"
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "asperity/math/enum_names.hpp"
#include "asperity/math/types.hpp"
#include "math/number_text.hpp"

namespace asperity::scene {

// Allowed values of a number; bounds may be open (excluded) or closed (included).
struct Range {
  double min = -1e300;
  double max = 1e300;
  bool min_open = false;
  bool max_open = false;

  static Range any() { return {}; }
  static Range positive(double max = 1e300) { return {0.0, max, true, false}; }
  static Range nonNegative(double max = 1e300) { return {0.0, max, false, false}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range leftOpen(double lo, double hi) { return {lo, hi, true, false}; }

  bool contains(double x) const;
  // A cap of 1e6 or more on a range from 0 (a sanity limit, named only when exceeded).
  bool softMax() const;
  // "a positive number", "a number in (0, 1]", ...
  std::string describe() const;
};

// Shortest text that reads back to the same double (math/number_text.hpp).
using asperity::formatNumber;

// Deepest nesting of arrays and objects that parseJsonText accepts (scenes need about 6).
inline constexpr int kMaxJsonDepth = 64;

// Parses JSON text; a syntax error becomes `file:line:column: what` (1-based line and column).
// Nesting deeper than kMaxJsonDepth is an error naming the depth, not a stack overflow.
nlohmann::json parseJsonText(const std::string& text, const std::string& file);
// Reads and parses a file; throws asperity::Error naming it when it cannot be read.
nlohmann::json parseJsonFile(const std::string& path);

class JsonReader {
 public:
  // `value` must outlive the reader. `pointer` is the JSON pointer of `value` ("" = document).
  JsonReader(const nlohmann::json& value, std::string file, std::string pointer = "");

  const nlohmann::json& value() const { return value_; }
  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }
  // The pointer of a member or element of this value.
  std::string childPointer(const std::string& key) const;
  std::string childPointer(size_t index) const;

  // Throws asperity::Error `file: pointer: what` (at this value, or at its member `key`).
  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void failAt(const std::string& key, const std::string& what) const;

  // Where warnings go, for this reader and the readers it hands out; null (the default): dropped.
  void setWarnings(std::vector<std::string>* warnings) { warnings_ = warnings; }
  // Records the warning `file: pointer/key: what`.
  void warnAt(const std::string& key, const std::string& what) const;
  // The key under which a renamed member is given: `current`, or `deprecated` with the warning
  // `file: /pointer/deprecated: deprecated, use "current"`; `current` when neither is present.
  // Both at once is an error at the deprecated key. Only `current` counts as a known key in
  // finish()'s list, unless the deprecated one is given.
  std::string renamed(const std::string& current, const std::string& deprecated);

  // Object members. Each getter marks the key as known; an absent key gives the default.
  bool has(const std::string& key);
  double number(const std::string& key, double fallback, Range range = Range::any());
  double requiredNumber(const std::string& key, Range range = Range::any());
  int integer(const std::string& key, int fallback, int min, int max);
  uint64_t unsignedInteger(const std::string& key, uint64_t fallback);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  std::string requiredString(const std::string& key);
  Vec3 vec3(const std::string& key, const Vec3& fallback, Range range = Range::any());
  Vec3 requiredVec3(const std::string& key, Range range = Range::any());
  // A non-zero vector, normalised ("must be a non-zero vector").
  Vec3 direction(const std::string& key, const Vec3& fallback);
  // [w, x, y, z], any non-zero length; normalised unless already unit to 1e-12.
  Quat quaternion(const std::string& key, const Quat& fallback);
  // One of the listed names; the error lists them all.
  template <typename E>
  E enumeration(const std::string& key, E fallback, EnumNames<E> names);

  // A member that must be an object; absent -> an empty object reader (nothing read).
  JsonReader object(const std::string& key);
  // A member that must be an array of objects; absent -> empty.
  std::vector<JsonReader> objects(const std::string& key);
  // A member that must be an array (of anything); absent -> empty.
  std::vector<JsonReader> elements(const std::string& key);

  // Errors on the first member that no getter asked for (objects only).
  void finish() const;

  // This value's own checks, for readers over arrays or scalars.
  void requireObject() const;
  double asNumber(Range range) const;
  Vec3 asVec3(Range range) const;

 private:
  // The member `key` if present (marking it known), else null.
  const nlohmann::json* member(const std::string& key);

  const nlohmann::json& value_;
  std::string file_;
  std::string pointer_;
  std::set<std::string> known_;
  std::vector<std::string>* warnings_ = nullptr;
};

// `one of "a", "b", "c"`.
std::string oneOf(const std::vector<std::string>& names);

// The "got ..." part of an error: a short rendering of the value and its JSON type.
std::string describeValue(const nlohmann::json& value);

template <typename E>
E JsonReader::enumeration(const std::string& key, E fallback, EnumNames<E> names) {
  const nlohmann::json* v = member(key);
  if (v == nullptr) return fallback;
  std::vector<std::string> list;
  for (const auto& [name, e] : names) {
    if (v->is_string() && v->get_ref<const std::string&>() == name) return e;
    list.emplace_back(name);
  }
  failAt(key, "must be " + oneOf(list) + ", got " + describeValue(*v));
}

// The name of an enumerator (for saving), or "" when absent from the list.
template <typename E>
std::string enumName(E value, EnumNames<E> names) {
  return nameOf(value, names);
}

}  // namespace asperity::scene
