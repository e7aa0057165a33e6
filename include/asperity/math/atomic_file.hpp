// Outputs that are never left cut short under their final names (docs/reliability.md): a whole
// file goes to a temporary name beside it and is renamed into place once complete; a file that
// grows record by record (a trajectory, a sweep's table) takes each record with one write(2),
// so a killed process leaves whole records only.
//
// A path that exists and is not a regular file (/dev/stdout, /dev/full, a pipe) is written
// directly: renaming over a device would replace it. Every failure is one asperity::Error,
// "PATH: write failed: REASON" (or "cannot open for writing"), naming the path given.
#pragma once

#include <string>
#include <string_view>

namespace asperity {

// `bytes` into `path`, whole or not at all (PATH.tmp, flushed to the disk, renamed).
void writeFileAtomically(const std::string& path, std::string_view bytes);

// For a writer that needs a file name of its own (an image encoder, ffmpeg): it writes to
// temporaryPath(); commit() renames that into place. Without commit() (an error, an exception)
// the destructor removes the temporary and the final name is left as it was.
class AtomicOutput {
 public:
  explicit AtomicOutput(std::string path);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::string& temporaryPath() const { return temporary_; }
  const std::string& finalPath() const { return path_; }
  void commit();

 private:
  std::string path_, temporary_;
  bool committed_ = false;
};

// A file written in records: truncated on opening (or, with `keep`, appended to), then each
// append() is one write(2) of whole records (straight to the kernel: nothing waits in a buffer
// when the process is killed).
class RecordFile {
 public:
  // `shown`: the name errors give (default: path).
  explicit RecordFile(const std::string& path, const std::string& shown = "", bool keep = false);
  ~RecordFile();
  RecordFile(const RecordFile&) = delete;
  RecordFile& operator=(const RecordFile&) = delete;

  void append(std::string_view records);
  // To the disk, not only to the kernel (at the end of a run). Not for devices and pipes.
  void sync();
  // A regular file (not a device or pipe): one that can be resumed or renamed.
  bool regular() const;

 private:
  std::string path_;
  int fd_;
};

}  // namespace asperity
