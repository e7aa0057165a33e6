// A world's worker threads (oneTBB). Work is split into independent items, each writing only
// its own slots, and anything combined afterwards is combined in item order: so a step gives
// the same bits on 1 thread as on 16 (SPEC 9), and 1 thread runs a plain loop with no pool.
#pragma once

#include <cstddef>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace asperity {

class ThreadPool {
 public:
  // `threads` workers: 0 = every core, 1 = the calling thread only. Throws asperity::Error
  // for a negative count.
  explicit ThreadPool(int threads);

  int requested() const { return requested_; }
  // Threads that work runs on (>= 1).
  int concurrency() const;

  // The slot of the thread running the current item of forEach, in [0, concurrency()):
  // per-thread scratch indexed by it is never shared by two items running at once. Items run
  // without the arena (few of them, or one thread) run on the calling thread alone: slot 0,
  // whatever other arena that thread works in (a sweep's).
  int slot() const {
    const int index = tbb::this_task_arena::current_thread_index();
    return index < 0 || index >= concurrency() ? 0 : index;
  }

  // body(i) for i in [0, count): items of at least `grain` go to one thread at a time.
  template <class Body>
  void forEach(size_t count, size_t grain, const Body& body) const {
    if (!arena_ || count <= grain) {
      for (size_t i = 0; i < count; ++i) body(i);
      return;
    }
    arena_->execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, count, grain),
                        [&](const tbb::blocked_range<size_t>& range) {
                          for (size_t i = range.begin(); i != range.end(); ++i) body(i);
                        });
    });
  }

 private:
  int requested_ = 1;
  std::unique_ptr<tbb::task_arena> arena_;  // null: one thread
};

// pool->forEach, or a plain loop when there is no pool (a caller without threads).
template <class Body>
void forEachOn(const ThreadPool* pool, size_t count, size_t grain, const Body& body) {
  if (pool) {
    pool->forEach(count, grain, body);
  } else {
    for (size_t i = 0; i < count; ++i) body(i);
  }
}

}  // namespace asperity
