#include "parallel/thread_pool.hpp"

#include <string>

#include "asperity/error.hpp"

namespace asperity {

ThreadPool::ThreadPool(int threads) : requested_(threads) {
  if (threads < 0)
    throw Error("threads must be >= 0 (0 = every core), got " + std::to_string(threads));
  if (threads == 1) return;
  // A copy of `automatic`: the header declares it without a definition to bind to.
  const int every_core = tbb::task_arena::automatic;
  arena_ = std::make_unique<tbb::task_arena>(threads == 0 ? every_core : threads);
}

int ThreadPool::concurrency() const {
  return arena_ ? arena_->max_concurrency() : 1;
}

}  // namespace asperity
