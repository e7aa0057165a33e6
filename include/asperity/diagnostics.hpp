// Warnings the library finds (a deprecated scene key, a normal map whose texels are not all
// normals, a green channel that contradicts the scene) are collected here instead of being
// printed: the library never writes to std::cerr. Each World owns one (World::diagnostics());
// front ends read the list or set a sink: the CLI prints `asperity: warning: <warning>`, Python
// calls warnings.warn. No global state; not safe to use from several threads at once.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace asperity {

class Diagnostics {
 public:
  // Receives each warning: one line naming its culprit, without an "asperity: warning: " prefix.
  using Sink = std::function<void(const std::string& warning)>;

  // Records a warning and hands it to the sink, if one is set.
  void warn(std::string warning) {
    warnings_.push_back(std::move(warning));
    if (sink_) sink_(warnings_.back());
  }

  // Hands every later warning to `sink`. The warnings recorded before are handed to it at once,
  // oldest first, so a sink set after the world is built (instantiate) misses none. An empty
  // sink only records.
  void setSink(Sink sink) {
    sink_ = std::move(sink);
    if (sink_)
      for (const std::string& w : warnings_) sink_(w);
  }

  // Every warning recorded so far, oldest first.
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Forgets the recorded warnings (the sink stays).
  void clear() { warnings_.clear(); }

 private:
  std::vector<std::string> warnings_;
  Sink sink_;
};

}  // namespace asperity
