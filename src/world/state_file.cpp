// Checkpoint files (asperity/world/state_file.hpp): a header that names the format and the
// scene, then World::saveState's bytes.
#include "asperity/world/state_file.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"
#include "asperity/math/state_stream.hpp"

namespace asperity {
namespace {

constexpr char kMagic[8] = {'A', 'S', 'P', 'S', 'T', 'A', 'T', 'E'};
// Written as a double: another byte order or number format reads it as something else.
constexpr double kByteOrderMark = 1.0 + 1.0 / 1024.0;
// Magic, format, mark, scene id, body count, length, checksum.
constexpr size_t kHeaderSize = sizeof(kMagic) + 4 + 8 * 5;

uint64_t checksum(std::string_view bytes) {
  uint64_t hash = 1469598103934665603ull;
  for (const unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string hex(uint64_t value) {
  char out[20];
  std::snprintf(out, sizeof(out), "%016llx", static_cast<unsigned long long>(value));
  return out;
}

// The first `count` bytes of the file from `offset`; short when the file is.
std::string readBytes(const std::string& path, uint64_t offset, uint64_t count) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot be read");
  in.seekg(static_cast<std::streamoff>(offset));
  std::string bytes(static_cast<size_t>(count), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(count));
  if (in.bad()) throw Error("cannot be read");
  bytes.resize(static_cast<size_t>(in.gcount()));
  return bytes;
}

// A state file is a regular file: a device, a FIFO or /dev/zero would be read without end.
uint64_t regularFileSize(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw Error("cannot be read");
  if (!std::filesystem::is_regular_file(status))
    throw Error("not a regular file (a folder, a device or a FIFO), so no state file");
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error("cannot be read");
  return size;
}

struct StateHeader {
  uint64_t length = 0;  // bytes of state after the header
  uint64_t sum = 0;     // their checksum
};

// The header (the file's first bytes) checked field by field against the file's size, before
// any byte of the state is read.
StateHeader checkHeader(std::string_view head, uint64_t file_size, const World& world,
                        uint64_t scene_id) {
  if (head.size() < sizeof(kMagic) || std::memcmp(head.data(), kMagic, sizeof(kMagic)) != 0)
    throw Error("not an Asperity state file (it does not start with ASPSTATE)");
  if (file_size < kHeaderSize)
    throw Error("truncated: " + std::to_string(file_size) + " bytes, shorter than the " +
                std::to_string(kHeaderSize) + "-byte header");
  StateReader in(head);
  char magic[sizeof(kMagic)];
  in.getBytes(magic, sizeof(magic));
  const auto format = in.get<uint32_t>();
  if (format != kStateFormat)
    throw Error("state format " + std::to_string(format) + ", this build reads format " +
                std::to_string(kStateFormat));
  if (in.get<double>() != kByteOrderMark)
    throw Error("written on a machine of another byte order or number format");
  const auto scene = in.get<uint64_t>();
  if (scene != scene_id)
    throw Error("saved from another scene (scene id " + hex(scene) + ", this scene's is " +
                hex(scene_id) + ")");
  in.expect<uint64_t>(world.bodies().size(), "bodies");
  StateHeader header;
  header.length = in.get<uint64_t>();
  header.sum = in.get<uint64_t>();
  const uint64_t left = file_size - kHeaderSize;
  if (header.length != left)
    throw Error("truncated or padded: the header promises " + std::to_string(header.length) +
                " bytes of state, the file holds " + std::to_string(left));
  return header;
}

}  // namespace

void saveStateFile(const World& world, const std::string& path, uint64_t scene_id) {
  const std::string state = world.saveState();
  StateWriter out;
  out.putBytes(kMagic, sizeof(kMagic));
  out.put(kStateFormat);
  out.put(kByteOrderMark);
  out.put(scene_id);
  out.put<uint64_t>(world.bodies().size());
  out.put<uint64_t>(state.size());
  out.put(checksum(state));
  out.putBytes(state.data(), state.size());
  writeFileAtomically(path, out.bytes());
}

void loadStateFile(World& world, const std::string& path, uint64_t scene_id) {
  try {
    // Size and header first, so that only a file its header describes is read whole.
    const uint64_t size = regularFileSize(path);
    const StateHeader header = checkHeader(readBytes(path, 0, kHeaderSize), size, world, scene_id);
    const std::string state = readBytes(path, kHeaderSize, header.length);
    if (state.size() != header.length) throw Error("cannot be read: it changed while being read");
    if (checksum(state) != header.sum) throw Error("corrupt: the state's checksum does not match");
    world.loadState(state);
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
}

}  // namespace asperity
