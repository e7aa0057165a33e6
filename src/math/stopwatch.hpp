// Wall-clock laps in milliseconds, for the stage times of a step's profile.
#pragma once

#include <chrono>

namespace asperity {

class Stopwatch {
 public:
  using Clock = std::chrono::steady_clock;

  // Milliseconds since the last lap (or since construction), and a new lap begins.
  double lap() {
    const Clock::time_point now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
    return ms;
  }
  // Milliseconds since construction.
  double total() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }

 private:
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_ = start_;
};

}  // namespace asperity
