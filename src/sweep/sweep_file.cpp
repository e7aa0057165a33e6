// A sweep written to its CSV file as it runs, and resumed from it (sweep.hpp, SweepFileOptions).
// Rows go out with one write(2) each, straight to the kernel: a killed process leaves whole
// rows only. The journal beside the file names the sweep, so that a resume with other
// arguments is refused instead of mixing two sweeps in one table; it stays beside the finished
// file, so a resume of that file is checked against it too. A lock beside the file lets one
// process at a time write it.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"
#include "asperity/sweep/sweep.hpp"

namespace asperity {
namespace {

constexpr int kJournalFormat = 1;

// FNV-1a of the scene's text: the journal names the scene without copying it.
std::string textHash(const std::string& text) {
  uint64_t hash = 1469598103934665603ull;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  char out[20];
  std::snprintf(out, sizeof(out), "%016llx", static_cast<unsigned long long>(hash));
  return out;
}

// What makes a sweep's table: the journal's content.
nlohmann::json journalOf(const Sweep& sweep) {
  const SweepDesc& d = sweep.desc();
  nlohmann::json vary = nlohmann::json::array();
  for (const Variation& v : d.vary)
    vary.push_back(
        {{"path", v.path}, {"distribution", static_cast<int>(v.distribution)}, {"args", v.args}});
  return {{"format", kJournalFormat},
          {"scene_file", d.scene_file},
          {"scene_hash", textHash(d.scene_json)},
          {"vary", vary},
          {"samples", d.samples},
          {"seed", d.seed},
          {"seconds", d.seconds},
          {"measures", d.measures}};
}

[[noreturn]] void failOn(const std::string& path, const std::string& what) {
  throw SweepFileError(path + ": " + what);
}

// The journal written atomically (a temporary file renamed into place), and the table's
// rows each with one write(2): asperity/math/atomic_file.hpp, its errors as SweepFileError.
template <typename F>
auto sweepFileCall(F&& call) {
  try {
    return call();
  } catch (const SweepFileError&) {
    throw;
  } catch (const Error& e) {
    throw SweepFileError(e.what());
  }
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) failOn(path, "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// An exclusive flock on FILE.lock, held while the sweep writes FILE; the system drops it when
// the process ends, however it ends. The lock file stays: removing it would let one process
// lock a file that another has just replaced.
class SweepLock {
 public:
  explicit SweepLock(const std::string& path) {
    const std::string lock = path + ".lock";
    fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0) failOn(path, "cannot open its lock " + lock + ": " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      char holder[32] = {};
      const ssize_t n = ::pread(fd_, holder, sizeof(holder) - 1, 0);
      ::close(fd_);
      failOn(path, "another sweep is writing it (process " + std::string(n > 0 ? holder : "?") +
                       " holds " + lock + ")");
    }
    // The holder's id only serves a second writer's message: failing to note it is no error.
    const std::string pid = std::to_string(::getpid());
    [[maybe_unused]] const bool noted =
        ::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) >= 0;
  }
  ~SweepLock() { ::close(fd_); }
  SweepLock(const SweepLock&) = delete;
  SweepLock& operator=(const SweepLock&) = delete;

 private:
  int fd_ = -1;
};

// Whether a kept row has the header's columns, each a finite number or a state hash (what a
// sample writes).
bool wellFormedRow(std::string_view row, size_t columns) {
  size_t count = 0;
  for (size_t start = 0; start <= row.size(); ++count) {
    const size_t comma = std::min(row.find(',', start), row.size());
    const std::string cell(row.substr(start, comma - start));
    char* end = nullptr;
    const double value = std::strtod(cell.c_str(), &end);
    const bool number = !cell.empty() && end == cell.c_str() + cell.size() && std::isfinite(value);
    // The state hash: 16 hex digits.
    const bool hash = cell.size() == 16 && cell.find_first_not_of("0123456789abcdef") == cell.npos;
    if (!number && !hash) return false;
    start = comma + 1;
  }
  return count == columns;
}

// The first key whose value differs between two journals ("" when none).
std::string firstDifference(const nlohmann::json& a, const nlohmann::json& b) {
  for (const auto& [key, value] : a.items())
    if (!b.contains(key) || b[key] != value) return key;
  return "";
}

// Length of the file's complete rows (header included), checking each is the next sample.
// Returns the count of sample rows in `rows`.
size_t completeLength(const std::string& text, const std::string& header, const std::string& path,
                      int64_t& rows) {
  if (text.compare(0, header.size(), header) != 0)
    failOn(path, "its header is not this sweep's columns: cannot resume");
  const size_t columns = static_cast<size_t>(std::count(header.begin(), header.end(), ',')) + 1;
  size_t end = header.size();
  rows = 0;
  for (size_t newline; (newline = text.find('\n', end)) != std::string::npos; end = newline + 1) {
    const std::string prefix = std::to_string(rows) + ",";
    const std::string line = "line " + std::to_string(rows + 2);
    if (text.compare(end, prefix.size(), prefix) != 0)
      failOn(path, line + " is not sample " + std::to_string(rows) + ": cannot resume");
    if (!wellFormedRow(std::string_view(text).substr(end, newline - end), columns))
      failOn(path, line + " (sample " + std::to_string(rows) + ") is not " +
                       std::to_string(columns) +
                       " numbers, as the sweep writes: the file was changed, cannot resume");
    ++rows;
  }
  return end;
}

// Where a resumed sweep starts: the file cut after its last whole row. -1: already complete.
int64_t resumePoint(const Sweep& sweep, const std::string& path, const std::string& journal) {
  if (!std::filesystem::exists(journal))
    failOn(path, "its journal " + journal + " is missing: nothing tells which sweep wrote it");
  const nlohmann::json written = nlohmann::json::parse(readText(journal), nullptr, false);
  if (written.is_discarded()) failOn(journal, "not a sweep journal (not valid JSON)");
  const std::string differs = firstDifference(journalOf(sweep), written);
  if (!differs.empty())
    failOn(journal, "written by another sweep (its " + differs +
                        " differs): run it again with the same arguments, or without resuming");
  const std::string text = readText(path);
  int64_t rows = 0;
  // Empty: killed after the journal, before the header (one write, so whole or absent).
  const size_t length = text.empty() ? 0 : completeLength(text, sweep.csvHeader(), path, rows);
  if (rows > sweep.desc().samples) failOn(path, "holds more rows than the sweep has samples");
  if (rows == sweep.desc().samples && length == text.size()) return -1;  // complete
  std::error_code error;
  std::filesystem::resize_file(path, length, error);
  if (error) failOn(path, "cannot be cut after its last whole row: " + error.message());
  return rows;
}

}  // namespace

std::string sweepJournalPath(const std::string& path) {
  return path + ".sweep";
}

std::string sweepJournal(const Sweep& sweep) {
  return journalOf(sweep).dump(2) + "\n";
}

int64_t runSweepToFile(const Sweep& sweep, const SweepFileOptions& options) {
  const std::string& path = options.path;
  const std::string journal = sweepJournalPath(path);
  // A regular file (or a new one) is locked; a device such as /dev/stdout is not.
  std::error_code kind_error;
  std::unique_ptr<SweepLock> lock;
  if (!std::filesystem::exists(path, kind_error) || std::filesystem::is_regular_file(path))
    lock = std::make_unique<SweepLock>(path);
  int64_t first = 0;
  // Resuming reads and cuts the file: through a link it would cut the file the link names.
  if (options.resume && std::filesystem::is_symlink(path))
    failOn(path, "is a symbolic link; a file is continued only under its own name");
  if (options.resume) {
    if (!std::filesystem::exists(path)) failOn(path, "nothing to resume: the file does not exist");
    first = resumePoint(sweep, path, journal);
    if (first < 0) return 0;
  }
  auto out = sweepFileCall([&] { return std::make_unique<RecordFile>(path, "", options.resume); });
  // Only a regular file can be resumed, so only it gets a journal (not /dev/stdout). The
  // journal is in place before the header: a file killed at any moment after its first line
  // can be resumed.
  const bool journaled = out->regular();
  if (!options.resume && journaled)
    sweepFileCall([&] { writeFileAtomically(journal, sweepJournal(sweep)); });
  if (!options.resume || std::filesystem::file_size(path) == 0)
    sweepFileCall([&] { out->append(sweep.csvHeader()); });
  sweep.runInOrder(options.threads, first, [&](const SampleResult& r) {
    sweepFileCall([&] { out->append(sweep.csvRow(r)); });
  });
  sweepFileCall([&] { out->sync(); });
  return sweep.desc().samples - first;
}

}  // namespace asperity
