// Private PNG reading and writing for the texture stage: header checks before any decoding,
// stb_image for decoding, and a small encoder for 8- and 16-bit images.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace asperity::png {

// PNG colour types (IHDR byte 9, file byte 25).
enum ColourType : int { kGrey = 0, kRgb = 2, kPalette = 3, kGreyAlpha = 4, kRgba = 6 };

// What the IHDR chunk says.
struct Header {
  int width = 0;
  int height = 0;
  int bit_depth = 0;
  int colour_type = 0;
};

// A decoded image: samples in [0, 1], rows top (first PNG row) to bottom, channels interleaved.
struct Image {
  Header header;
  int channels = 0;
  std::vector<float> samples;
};

// CRC-32 of the PNG specification (ISO 3309, polynomial 0xEDB88320).
uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0);

// Reads a whole file; throws asperity::Error naming the file if it cannot be opened.
std::vector<uint8_t> readFile(const std::string& path);

// Checks the signature, every chunk's length and CRC, IHDR first and IEND last, and the image
// size against max_size, all without decoding. Throws asperity::Error naming `path`.
Header inspect(const std::vector<uint8_t>& bytes, const std::string& path, int max_size);

// Decodes to `channels` channels (stb converts: grey <-> RGB, palettes expanded). 16-bit files
// keep 16-bit precision. Throws asperity::Error naming `path`.
Image decode(const std::vector<uint8_t>& bytes, const std::string& path, int max_size,
             int channels);

// True when the bytes start with the PNG signature.
bool isPng(const std::vector<uint8_t>& bytes);

// Decodes a PNG (as decode) or any other format stb reads (JPEG, BMP, TGA) to 8-bit
// `channels`, checking the size stb reports against max_size before decoding. Throws
// asperity::Error naming `path`.
Image decodeAny(const std::vector<uint8_t>& bytes, const std::string& path, int max_size,
                int channels);

// One tEXt chunk: a Latin-1 keyword (1 to 79 characters) and its text.
struct TextEntry {
  std::string key;
  std::string text;
};

// Writes an 8- or 16-bit RGB / RGBA / grey image, rows top to bottom; samples are the raw
// integer values (0..255 or 0..65535), with `text` as tEXt chunks before the image data.
// Throws asperity::Error naming `path`.
void write(const std::string& path, int width, int height, int channels, int bits,
           const std::vector<uint16_t>& samples, const std::vector<TextEntry>& text = {});

// The tEXt chunks of a PNG already checked by inspect(), in file order.
std::vector<TextEntry> readText(const std::vector<uint8_t>& bytes);

}  // namespace asperity::png
