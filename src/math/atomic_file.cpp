// Whole outputs by rename, growing outputs by whole records (asperity/math/atomic_file.hpp).
#include "asperity/math/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

#include "asperity/error.hpp"

namespace asperity {
namespace {

[[noreturn]] void failOn(const std::string& path, const std::string& what) {
  throw Error(path + ": " + what + ": " + std::strerror(errno));
}

// True when `path` names something other than a regular file (a device, a pipe): written in
// place, never renamed over.
bool special(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

void writeAll(int fd, std::string_view bytes, const std::string& path) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) errno = ENOSPC;
    if (n <= 0) failOn(path, "write failed");
    done += static_cast<size_t>(n);
  }
}

// An output names the path it is given: a symbolic link there to a regular file (or to
// nothing) is replaced, never written through into the file it names, and is refused when
// the output would continue that file. A link to a device or pipe (/dev/stdout is one) is
// written in place.
int openForWriting(const std::string& path, const std::string& shown, bool keep) {
  struct stat entry {};
  const bool in_place = special(path);
  if (!in_place && ::lstat(path.c_str(), &entry) == 0 && S_ISLNK(entry.st_mode)) {
    if (keep)
      throw Error(shown + ": is a symbolic link; a file is continued only under its own name");
    if (::unlink(path.c_str()) != 0) failOn(shown, "cannot replace the symbolic link");
  }
  const int flags =
      O_WRONLY | O_CREAT | O_CLOEXEC | (keep ? O_APPEND : O_TRUNC) | (in_place ? 0 : O_NOFOLLOW);
  const int fd = ::open(path.c_str(), flags, 0644);
  if (fd < 0) failOn(shown, "cannot open for writing");
  return fd;
}

std::string temporaryFor(const std::string& path) {
  return special(path) ? path : path + ".tmp";
}

}  // namespace

void writeFileAtomically(const std::string& path, std::string_view bytes) {
  AtomicOutput out(path);
  {
    // Errors name the path asked for, not the temporary.
    RecordFile file(out.temporaryPath(), path);
    file.append(bytes);
    file.sync();
  }
  out.commit();
}

AtomicOutput::AtomicOutput(std::string path)
    : path_(std::move(path)), temporary_(temporaryFor(path_)) {}

AtomicOutput::~AtomicOutput() {
  if (!committed_ && temporary_ != path_) std::remove(temporary_.c_str());
}

void AtomicOutput::commit() {
  committed_ = true;
  if (temporary_ == path_) return;
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary_.c_str());
    errno = error;
    failOn(path_, "cannot write");
  }
}

RecordFile::RecordFile(const std::string& path, const std::string& shown, bool keep)
    : path_(shown.empty() ? path : shown), fd_(openForWriting(path, path_, keep)) {}

bool RecordFile::regular() const {
  struct stat st {};
  return ::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode);
}

RecordFile::~RecordFile() {
  ::close(fd_);
}

void RecordFile::append(std::string_view records) {
  writeAll(fd_, records, path_);
}

void RecordFile::sync() {
  // A device or pipe has nothing to flush (and may refuse).
  if (regular() && ::fsync(fd_) != 0) failOn(path_, "write failed");
}

}  // namespace asperity
