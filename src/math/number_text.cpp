// Numbers as text (math/number_text.hpp).
#include "math/number_text.hpp"

#include <charconv>
#include <cmath>

namespace asperity {

std::string formatNumber(double x) {
  char buffer[64];
  const bool whole = std::isfinite(x) && x == std::trunc(x) && std::abs(x) < 1e16;
  const auto result =
      whole ? std::to_chars(buffer, buffer + sizeof(buffer), x, std::chars_format::fixed)
            : std::to_chars(buffer, buffer + sizeof(buffer), x);
  return std::string(buffer, result.ptr);
}

}  // namespace asperity
