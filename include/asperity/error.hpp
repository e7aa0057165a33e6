// The one exception type of the library. Its message is a single line that names the culprit
// (a file, a JSON path, a parameter) and what is wrong; front ends print it and exit non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace asperity {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace asperity
