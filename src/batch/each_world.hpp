// Work over some of a batch's worlds on its pool: every world runs, whatever another throws,
// and the error reported is that of the lowest world, so it does not depend on the threads.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "asperity/error.hpp"
#include "parallel/thread_pool.hpp"

namespace asperity {

// body(i) for every i of `worlds`, one world to a task. Returns "world i: what" for the lowest
// i whose body threw asperity::Error, or "" when none did.
template <class Body>
std::string eachWorld(const ThreadPool& pool, std::span<const size_t> worlds, const Body& body) {
  std::vector<std::string> errors(worlds.size());
  pool.forEach(worlds.size(), 1, [&](size_t k) {
    try {
      body(worlds[k]);
    } catch (const Error& e) {
      errors[k] = "world " + std::to_string(worlds[k]) + ": " + e.what();
    }
  });
  // Worlds are listed in increasing order: the first error is the lowest world's.
  for (const std::string& e : errors)
    if (!e.empty()) return e;
  return {};
}

}  // namespace asperity
