// PNG reading (stb_image after our own header checks) and writing (our chunks, stb's deflate).
// This file is the one place that compiles the stb_image and stb_image_write implementations.
#include "texture/png_codec.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <utility>

#include <zlib.h>

#include "asperity/error.hpp"
#include "asperity/math/atomic_file.hpp"
#include "asperity/texture/png_io.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include "stb_image.h"
#include "stb_image_write.h"
#pragma GCC diagnostic pop

namespace asperity::png {

namespace {

constexpr std::array<uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw Error("PNG file '" + path + "': " + what);
}

uint32_t readBigEndian32(const uint8_t* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | uint32_t{p[3]};
}

void appendBigEndian32(std::vector<uint8_t>& out, uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) {
    out.push_back(static_cast<uint8_t>((value >> shift) & 0xffu));
  }
}

// Checks IHDR's fields: size first (never allocate for absurd sizes), then the sample format.
Header parseIhdr(const uint8_t* data, const std::string& path, int max_size) {
  Header h;
  const uint32_t w = readBigEndian32(data);
  const uint32_t hgt = readBigEndian32(data + 4);
  if (w == 0 || hgt == 0) {
    fail(path, "zero-sized image (" + std::to_string(w) + " x " + std::to_string(hgt) + ")");
  }
  const auto limit = static_cast<uint32_t>(max_size);
  if (w > limit || hgt > limit) {
    fail(path, "image of " + std::to_string(w) + " x " + std::to_string(hgt) +
                   " texels exceeds the limit of " + std::to_string(max_size) + " per side");
  }
  h.width = static_cast<int>(w);
  h.height = static_cast<int>(hgt);
  h.bit_depth = data[8];
  h.colour_type = data[9];
  // Colour type and bit depth pairs allowed by the PNG specification.
  const int bd = h.bit_depth;
  const bool grey_ok = bd == 1 || bd == 2 || bd == 4 || bd == 8 || bd == 16;
  const bool ok =
      (h.colour_type == kGrey && grey_ok) || (h.colour_type == kPalette && bd <= 8 && grey_ok) ||
      ((h.colour_type == kRgb || h.colour_type == kGreyAlpha || h.colour_type == kRgba) &&
       (bd == 8 || bd == 16));
  if (!ok) {
    fail(path, "corrupt header (colour type " + std::to_string(h.colour_type) + ", bit depth " +
                   std::to_string(bd) + ")");
  }
  return h;
}

// Appends one chunk (length, type, data, CRC over type and data).
void appendChunk(std::vector<uint8_t>& out, const char* type, const uint8_t* data, size_t size) {
  appendBigEndian32(out, static_cast<uint32_t>(size));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  appendBigEndian32(out, crc32(out.data() + start, size + 4));
}

}  // namespace

uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc) {
  // zlib's CRC-32 is PNG's (ISO 3309) and several times faster than a byte-wise table.
  return static_cast<uint32_t>(::crc32_z(crc, data, size));
}

std::vector<uint8_t> readFile(const std::string& path) {
  std::optional<std::vector<uint8_t>> bytes = readFileBytes(path);
  if (!bytes) {
    // Why, only once it failed (readFileBytes refuses directories too).
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a file");
    fail(path, "cannot open (missing or unreadable)");
  }
  return std::move(*bytes);
}

Header inspect(const std::vector<uint8_t>& bytes, const std::string& path, int max_size) {
  // Signature.
  if (bytes.size() < kSignature.size() ||
      !std::equal(kSignature.begin(), kSignature.end(), bytes.begin())) {
    fail(path, bytes.empty() ? "empty file" : "not a PNG file (bad signature)");
  }
  // Walk the chunks: each must fit in the file and match its CRC; IHDR first, IEND last.
  Header header;
  size_t pos = kSignature.size();
  for (bool first = true;; first = false) {
    if (bytes.size() - pos < 12) {
      fail(path, "truncated (no IEND chunk)");
    }
    const uint32_t length = readBigEndian32(&bytes[pos]);
    const std::string type(reinterpret_cast<const char*>(&bytes[pos + 4]), 4);
    if (length > 0x7fffffffu || bytes.size() - pos - 12 < length) {
      fail(path, "truncated (chunk '" + type + "' runs past the end of the file)");
    }
    const uint32_t stored = readBigEndian32(&bytes[pos + 8 + length]);
    if (crc32(&bytes[pos + 4], length + 4) != stored) {
      fail(path, "corrupt (CRC mismatch in chunk '" + type + "')");
    }
    if (first != (type == "IHDR") || (first && length != 13)) {
      fail(path, "corrupt (the first chunk must be a 13-byte IHDR)");
    }
    if (first) {
      header = parseIhdr(&bytes[pos + 8], path, max_size);
    }
    pos += 12 + length;
    if (type == "IEND") {
      return header;
    }
  }
}

Image decode(const std::vector<uint8_t>& bytes, const std::string& path, int max_size,
             int channels) {
  Image image;
  image.header = inspect(bytes, path, max_size);
  image.channels = channels;
  if (bytes.size() > static_cast<size_t>(INT_MAX)) {
    fail(path, "file too large");
  }
  // Decode with stb at the file's precision.
  const bool deep = image.header.bit_depth == 16;
  const auto len = static_cast<int>(bytes.size());
  int w = 0;
  int h = 0;
  int in_file = 0;
  void* raw = deep ? static_cast<void*>(
                         stbi_load_16_from_memory(bytes.data(), len, &w, &h, &in_file, channels))
                   : static_cast<void*>(
                         stbi_load_from_memory(bytes.data(), len, &w, &h, &in_file, channels));
  std::unique_ptr<void, void (*)(void*)> owner(raw, stbi_image_free);
  if (raw == nullptr) {
    fail(path, std::string("corrupt image data (") + stbi_failure_reason() + ")");
  }
  if (w != image.header.width || h != image.header.height) {
    fail(path, "corrupt (decoded size differs from the header)");
  }
  // Convert to [0, 1].
  const size_t count = static_cast<size_t>(w) * static_cast<size_t>(h) * channels;
  image.samples.resize(count);
  for (size_t k = 0; k < count; ++k) {
    image.samples[k] = deep ? static_cast<float>(static_cast<const uint16_t*>(raw)[k]) / 65535.0f
                            : static_cast<float>(static_cast<const uint8_t*>(raw)[k]) / 255.0f;
  }
  return image;
}

void write(const std::string& path, int width, int height, int channels, int bits,
           const std::vector<uint16_t>& samples, const std::vector<TextEntry>& text) {
  // Raw scanlines: filter byte 0 (None), then big-endian samples.
  const size_t bytes_per_sample = bits == 16 ? 2 : 1;
  const size_t row_bytes = 1 + static_cast<size_t>(width) * channels * bytes_per_sample;
  std::vector<uint8_t> raw;
  raw.reserve(row_bytes * static_cast<size_t>(height));
  for (size_t k = 0; k < samples.size(); ++k) {
    if (k % (static_cast<size_t>(width) * channels) == 0) {
      raw.push_back(0);
    }
    if (bits == 16) {
      raw.push_back(static_cast<uint8_t>(samples[k] >> 8));
    }
    raw.push_back(static_cast<uint8_t>(samples[k] & 0xffu));
  }
  // zlib stream from stb_image_write's deflate.
  int compressed_size = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> compressed(
      stbi_zlib_compress(raw.data(), static_cast<int>(raw.size()), &compressed_size, 8), std::free);
  if (!compressed) {
    fail(path, "compression failed");
  }
  // Signature, IHDR, IDAT, IEND.
  std::vector<uint8_t> out(kSignature.begin(), kSignature.end());
  std::vector<uint8_t> ihdr;
  appendBigEndian32(ihdr, static_cast<uint32_t>(width));
  appendBigEndian32(ihdr, static_cast<uint32_t>(height));
  const int colour = channels == 4   ? kRgba
                     : channels == 3 ? kRgb
                     : channels == 2 ? kGreyAlpha
                                     : kGrey;
  ihdr.insert(ihdr.end(), {static_cast<uint8_t>(bits), static_cast<uint8_t>(colour), 0, 0, 0});
  appendChunk(out, "IHDR", ihdr.data(), ihdr.size());
  for (const TextEntry& entry : text) {
    // tEXt: keyword, a zero byte, then the text.
    if (entry.key.empty() || entry.key.size() > 79) fail(path, "bad text key '" + entry.key + "'");
    std::vector<uint8_t> data(entry.key.begin(), entry.key.end());
    data.push_back(0);
    data.insert(data.end(), entry.text.begin(), entry.text.end());
    appendChunk(out, "tEXt", data.data(), data.size());
  }
  appendChunk(out, "IDAT", compressed.get(), static_cast<size_t>(compressed_size));
  appendChunk(out, "IEND", nullptr, 0);
  // Written whole under a temporary name, then renamed (asperity/math/atomic_file.hpp).
  try {
    writeFileAtomically(path, {reinterpret_cast<const char*>(out.data()), out.size()});
  } catch (const Error& e) {
    // The helper's "PATH: reason" without the path, which fail() names itself.
    const std::string reason = e.what();
    fail(path, "cannot write (" + reason.substr(reason.find(": ") + 2) + ")");
  }
}

std::vector<TextEntry> readText(const std::vector<uint8_t>& bytes) {
  // The chunk walk of inspect(), trusting its checks; a keyword without its zero byte is skipped.
  std::vector<TextEntry> entries;
  for (size_t pos = kSignature.size(); pos + 12 <= bytes.size();) {
    const uint32_t length = readBigEndian32(&bytes[pos]);
    const std::string type(reinterpret_cast<const char*>(&bytes[pos + 4]), 4);
    if (type == "IEND" || bytes.size() - pos - 12 < length) break;
    if (type == "tEXt") {
      const auto* first = reinterpret_cast<const char*>(&bytes[pos + 8]);
      const std::string data(first, length);
      if (const size_t zero = data.find('\0'); zero != std::string::npos)
        entries.push_back({data.substr(0, zero), data.substr(zero + 1)});
    }
    pos += 12 + length;
  }
  return entries;
}

bool isPng(const std::vector<uint8_t>& bytes) {
  return bytes.size() >= kSignature.size() &&
         std::equal(kSignature.begin(), kSignature.end(), bytes.begin());
}

Image decodeAny(const std::vector<uint8_t>& bytes, const std::string& path, int max_size,
                int channels) {
  // PNGs get the full chunk checks; other formats only stb's own.
  if (isPng(bytes)) return decode(bytes, path, max_size, channels);
  if (bytes.empty() || bytes.size() > static_cast<size_t>(INT_MAX)) {
    throw Error("image '" + path + "': empty or too large");
  }
  const auto len = static_cast<int>(bytes.size());
  int w = 0, h = 0, in_file = 0;
  // Size first: never allocate for an absurd header.
  if (stbi_info_from_memory(bytes.data(), len, &w, &h, &in_file) == 0) {
    throw Error("image '" + path + "': not a PNG, JPEG, BMP or TGA image (" +
                stbi_failure_reason() + ")");
  }
  if (w <= 0 || h <= 0 || w > max_size || h > max_size) {
    throw Error("image '" + path + "': image of " + std::to_string(w) + " x " + std::to_string(h) +
                " texels exceeds the limit of " + std::to_string(max_size) + " per side");
  }
  // Decode to 8 bits per channel and convert to [0, 1].
  std::unique_ptr<stbi_uc, void (*)(void*)> raw(
      stbi_load_from_memory(bytes.data(), len, &w, &h, &in_file, channels), stbi_image_free);
  if (!raw) throw Error("image '" + path + "': corrupt image data (" + stbi_failure_reason() + ")");
  Image image;
  image.header = {w, h, 8, channels == 1 ? kGrey : kRgb};
  image.channels = channels;
  const size_t count = static_cast<size_t>(w) * static_cast<size_t>(h) * channels;
  image.samples.resize(count);
  for (size_t k = 0; k < count; ++k) image.samples[k] = static_cast<float>(raw.get()[k]) / 255.0f;
  return image;
}

}  // namespace asperity::png
