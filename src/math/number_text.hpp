// Numbers as text for messages and files (internal).
#pragma once

#include <string>

namespace asperity {

// Shortest text that reads back to the same double ("0.1", "-3", "1e+300"); whole numbers
// below 1e16 in full ("1000000", not "1e+06").
std::string formatNumber(double x);

}  // namespace asperity
