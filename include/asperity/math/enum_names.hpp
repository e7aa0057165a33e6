// The names of enumerations as scene files, the command line and Python spell them. Each
// enumeration keeps its table beside its definition (e.g. kLimitSurfaceNames in
// friction/limit_surface.hpp); these two functions read any of them.
#pragma once

#include <span>
#include <string>
#include <type_traits>
#include <utility>

#include "asperity/error.hpp"

namespace asperity {

// A table of (name, value) pairs; as a parameter it is not deduced, so that a table given as
// an array converts once E is known from another argument.
template <typename E>
using EnumNames = std::type_identity_t<std::span<const std::pair<const char*, E>>>;

// The name of `value`, or "" when the table lacks it.
template <typename E>
const char* nameOf(E value, EnumNames<E> names) {
  for (const auto& [name, e] : names)
    if (e == value) return name;
  return "";
}

// The value called `name`. Throws asperity::Error
// `WHAT: unknown value 'x' (available: a, b, c)`.
template <typename E>
E parseName(const std::string& name, EnumNames<E> names, const std::string& what) {
  std::string known;
  for (const auto& [n, e] : names) {
    if (name == n) return e;
    known += (known.empty() ? "" : ", ") + std::string(n);
  }
  throw Error(what + ": unknown value '" + name + "' (available: " + known + ")");
}

}  // namespace asperity
