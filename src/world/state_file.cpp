// Checkpoint files (asperity/world/state_file.hpp): a header that names the format and the
// scene, then World::saveState's bytes.
#include "asperity/world/state_file.hpp"

#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
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

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(path + ": cannot be read");
  return text.str();
}

// The header checked field by field; returns the state's bytes.
std::string_view checkHeader(StateReader& in, std::string_view file, const World& world,
                             uint64_t scene_id) {
  if (file.size() < sizeof(kMagic) || std::memcmp(file.data(), kMagic, sizeof(kMagic)) != 0)
    throw Error("not an Asperity state file (it does not start with ASPSTATE)");
  if (file.size() < kHeaderSize)
    throw Error("truncated: " + std::to_string(file.size()) + " bytes, shorter than the " +
                std::to_string(kHeaderSize) + "-byte header");
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
  const auto length = in.get<uint64_t>();
  const auto sum = in.get<uint64_t>();
  const size_t left = file.size() - in.offset();
  if (length != left)
    throw Error("truncated or padded: the header promises " + std::to_string(length) +
                " bytes of state, the file holds " + std::to_string(left));
  const std::string_view state = file.substr(in.offset());
  if (checksum(state) != sum) throw Error("corrupt: the state's checksum does not match");
  return state;
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
  const std::string file = readFile(path);
  try {
    StateReader header(file);
    world.loadState(checkHeader(header, file, world, scene_id));
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
}

}  // namespace asperity
