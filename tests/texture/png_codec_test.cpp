// PNG codec internals: the CRC-32 check value and a grey 16-bit round trip (height maps use it).
#include "texture/png_codec.hpp"

#include <gtest/gtest.h>

#include <string>

#include "support/test_support.hpp"

namespace asperity {
namespace {

TEST(PngCodec, Crc32CheckValue) {
  // The standard check value of CRC-32 for "123456789".
  const std::string s = "123456789";
  EXPECT_EQ(png::crc32(reinterpret_cast<const uint8_t*>(s.data()), s.size()), 0xCBF43926u);
}

TEST(PngCodec, Grey16RoundTripIsExact) {
  const std::string path = test::tempDir("codec") + "/grey16.png";
  const std::vector<uint16_t> samples = {0, 1, 2, 65535, 40000, 12345};
  png::write(path, 3, 2, 1, 16, samples);
  const png::Image image = png::decode(png::readFile(path), path, 16, 1);
  EXPECT_EQ(image.header.bit_depth, 16);
  EXPECT_EQ(image.header.colour_type, png::kGrey);
  ASSERT_EQ(image.samples.size(), samples.size());
  for (size_t k = 0; k < samples.size(); ++k) {
    EXPECT_EQ(image.samples[k], static_cast<float>(samples[k]) / 65535.0f);
  }
}

}  // namespace
}  // namespace asperity
