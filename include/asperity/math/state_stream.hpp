// The bytes of a world's saved state (World::saveState, docs/checkpoints.md): each stage writes
// what its next step depends on into a StateWriter and reads it back from a StateReader. Values
// go in as their bit patterns (the machine's byte order), so a state read back is the same bits;
// a state file is for the build and machine kind that wrote it (its header says which format).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "asperity/error.hpp"

namespace asperity {

// Plain values only: no pointers or owning members in what is copied bytewise.
template <typename T>
concept StateValue = std::is_standard_layout_v<T> && !std::is_pointer_v<T>;

class StateWriter {
 public:
  template <StateValue T>
  void put(const T& value) {
    putBytes(&value, sizeof(T));
  }
  void putBytes(const void* data, size_t size) {
    if (size == 0) return;  // as in getBytes: data may be null
    const auto* p = static_cast<const char*>(data);
    bytes_.append(p, size);
  }
  void putString(std::string_view text) {
    put<uint64_t>(text.size());
    bytes_.append(text);
  }
  // A count, then the elements' bytes.
  template <StateValue T>
  void putVector(const std::vector<T>& values) {
    put<uint64_t>(values.size());
    putBytes(values.data(), values.size() * sizeof(T));
  }
  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Reads what a StateWriter wrote, in the same order. Reading past the end throws
// asperity::Error ("ends early"), so a truncated state is an error, never a wild read.
class StateReader {
 public:
  explicit StateReader(std::string_view bytes) : bytes_(bytes) {}

  template <StateValue T>
  T get() {
    T value;
    getBytes(&value, sizeof(T));
    return value;
  }
  void getBytes(void* out, size_t size) {
    need(size);
    if (size == 0) return;  // an empty vector's data() may be null, which memcpy must not get
    std::memcpy(out, bytes_.data() + at_, size);
    at_ += size;
  }
  std::string getString() {
    std::string text(count(1), '\0');
    getBytes(text.data(), text.size());
    return text;
  }
  template <StateValue T>
  void getVector(std::vector<T>& out) {
    out.resize(count(sizeof(T)));
    getBytes(out.data(), out.size() * sizeof(T));
  }
  // A count of elements of `size` bytes each, checked against what is left (a corrupt count
  // would otherwise ask for terabytes).
  size_t count(size_t size) {
    const auto n = get<uint64_t>();
    if (size > 0 && n > (bytes_.size() - at_) / size) fail("a count of " + std::to_string(n));
    return static_cast<size_t>(n);
  }
  // Throws unless `actual` equals `expected`: what the state holds against what this world has.
  template <typename T>
  void expect(T expected, const std::string& what) {
    const auto actual = get<T>();
    if (actual != expected)
      throw Error("the state holds " + std::to_string(actual) + " " + what + ", this world has " +
                  std::to_string(expected));
  }
  bool done() const { return at_ == bytes_.size(); }
  size_t offset() const { return at_; }

 private:
  void need(size_t size) const {
    if (size > bytes_.size() - at_) fail(std::to_string(size) + " more bytes");
  }
  [[noreturn]] void fail(const std::string& wanted) const {
    throw Error("the state ends early (at byte " + std::to_string(at_) + " of " +
                std::to_string(bytes_.size()) + ", reading " + wanted + ")");
  }

  std::string_view bytes_;
  size_t at_ = 0;
};

}  // namespace asperity
