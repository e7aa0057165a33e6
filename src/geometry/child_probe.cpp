// Running untrusted parsing in a forked child first (geometry/child_probe.hpp).
#include "geometry/child_probe.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <thread>

#include "asperity/error.hpp"

namespace asperity::detail {

namespace {

// The child's exit code when `work` ran to its end; any other ending is a crash.
constexpr int kFinished = 0;

// A process's resident memory in bytes (0 when /proc cannot tell).
size_t residentBytes(pid_t pid) {
  const std::string path = "/proc/" + std::to_string(pid) + "/statm";
  std::FILE* file = std::fopen(path.c_str(), "r");
  if (file == nullptr) return 0;
  unsigned long size = 0, resident = 0;  // pages
  const int read = std::fscanf(file, "%lu %lu", &size, &resident);
  std::fclose(file);
  return read == 2 ? resident * static_cast<size_t>(::sysconf(_SC_PAGESIZE)) : 0;
}

// Kills the child and reaps it.
void stop(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
}

std::string formatted(const char* format, double value) {
  char text[32];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

void silenceStandardError() {
  const int null = ::open("/dev/null", O_WRONLY);
  if (null < 0) return;
  ::dup2(null, STDERR_FILENO);
  ::close(null);
}

}  // namespace

void probeInChild(const std::string& what, const std::function<void()>& work,
                  const ProbeLimits& limits) {
  // The child starts sharing the caller's pages, which its resident count includes.
  const size_t memory_cap = residentBytes(::getpid()) + limits.memory_bytes;
  const pid_t pid = ::fork();
  if (pid < 0) return;  // no child to spare: the caller reads in-process, as without the guard
  if (pid == 0) {
    // The child only runs the work, silently: what a crashing importer (or a sanitizer
    // watching it) prints is noise, as the parent reports the crash in one line. _exit
    // skips the parent's exit handlers and destructors.
    silenceStandardError();
    try {
      work();
    } catch (...) {
    }
    ::_exit(kFinished);
  }
  const auto deadline = std::chrono::steady_clock::now() + limits.time;
  int status = 0;
  pid_t done = 0;
  while ((done = ::waitpid(pid, &status, WNOHANG)) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      stop(pid);
      throw Error(what + ": reading it did not finish within " +
                  formatted("%g", static_cast<double>(limits.time.count()) / 1000.0) +
                  " s (the file is malformed)");
    }
    if (residentBytes(pid) > memory_cap) {
      stop(pid);
      throw Error(what + ": reading it took more than " +
                  formatted("%.0f", static_cast<double>(limits.memory_bytes) / (1 << 20)) +
                  " MB of memory (the file is malformed, or too large to read)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (done < 0) return;  // the child was reaped elsewhere: nothing to tell
  if (WIFEXITED(status) && WEXITSTATUS(status) == kFinished) return;
  const std::string how = WIFSIGNALED(status) ? "signal " + std::to_string(WTERMSIG(status))
                                              : "exit code " + std::to_string(WEXITSTATUS(status));
  throw Error(what + ": the importer crashed reading it (" + how + "; the file is malformed)");
}

}  // namespace asperity::detail
