// libFuzzer target: PNG bytes through the chunk checker and the decoder, at every channel
// count the library asks for. Bad files must end in asperity::Error.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "asperity/error.hpp"
#include "texture/png_codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<uint8_t> bytes(data, data + size);
  // A small size cap keeps decompression bombs cheap; the cap itself is what is checked.
  constexpr int kMaxSize = 512;
  try {
    asperity::png::inspect(bytes, "fuzz.png", kMaxSize);
  } catch (const asperity::Error&) {
    return 0;
  }
  for (int channels : {1, 3, 4}) {
    try {
      asperity::png::decode(bytes, "fuzz.png", kMaxSize, channels);
    } catch (const asperity::Error&) {
      // Rejected with a message naming the file: expected for bad input.
    }
  }
  return 0;
}
