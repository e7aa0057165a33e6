// Running untrusted parsing in a forked child first (geometry/child_probe.hpp).
#include "geometry/child_probe.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <thread>

#include "asperity/error.hpp"

namespace asperity::detail {

namespace {

// The child's exit code when `work` ran to its end; any other ending is a crash.
constexpr int kFinished = 0;

void silenceStandardError() {
  const int null = ::open("/dev/null", O_WRONLY);
  if (null < 0) return;
  ::dup2(null, STDERR_FILENO);
  ::close(null);
}

}  // namespace

void probeInChild(const std::string& what, const std::function<void()>& work,
                  std::chrono::milliseconds limit) {
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
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  pid_t done = 0;
  while ((done = ::waitpid(pid, &status, WNOHANG)) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      char seconds[32];
      std::snprintf(seconds, sizeof(seconds), "%g", static_cast<double>(limit.count()) / 1000.0);
      throw Error(what + ": reading it did not finish within " + seconds +
                  " s (the file is malformed)");
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
