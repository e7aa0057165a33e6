// PNG normal maps: round trips (8/16 bit, RGB/RGBA, both green conventions), row order, and one
// test per kind of bad file.
#include "asperity/texture/png_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "asperity/error.hpp"
#include "support/test_support.hpp"
#include "texture/png_codec.hpp"

namespace asperity {
namespace {

using test::near;

// A map of varied unit normals, all facing out of the surface.
NormalMap variedMap(int w, int h) {
  NormalMap map(w, h);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> tilt(-0.9f, 0.9f);
  for (Vec3f& m : const_cast<std::vector<Vec3f>&>(map.texels())) {
    m = Vec3f(tilt(rng), tilt(rng), 1.0f).normalized();
  }
  return map;
}

// Largest per-component difference between two maps of equal size.
double maxDifference(const NormalMap& a, const NormalMap& b) {
  EXPECT_EQ(a.width(), b.width());
  EXPECT_EQ(a.height(), b.height());
  double worst = 0.0;
  for (size_t k = 0; k < a.texels().size(); ++k) {
    worst =
        std::max(worst, static_cast<double>((a.texels()[k] - b.texels()[k]).cwiseAbs().maxCoeff()));
  }
  return worst;
}

// Expects fn to throw asperity::Error whose message contains every fragment.
template <class Fn>
void expectError(Fn fn, std::initializer_list<std::string> fragments) {
  try {
    fn();
    ADD_FAILURE() << "no asperity::Error thrown";
  } catch (const Error& e) {
    const std::string what = e.what();
    for (const std::string& f : fragments) {
      EXPECT_NE(what.find(f), std::string::npos) << "'" << f << "' not in: " << what;
    }
    EXPECT_EQ(what.find('\n'), std::string::npos) << "message must be one line";
  }
}

void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

void appendU32(std::vector<uint8_t>& out, uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<uint8_t>(v >> s));
}

void appendChunk(std::vector<uint8_t>& out, const std::string& type, std::vector<uint8_t> data) {
  appendU32(out, static_cast<uint32_t>(data.size()));
  std::vector<uint8_t> body(type.begin(), type.end());
  body.insert(body.end(), data.begin(), data.end());
  out.insert(out.end(), body.begin(), body.end());
  appendU32(out, png::crc32(body.data(), body.size()));
}

// A zlib stream holding `raw` in one stored (uncompressed) deflate block.
std::vector<uint8_t> storedZlib(const std::vector<uint8_t>& raw) {
  std::vector<uint8_t> z = {0x78, 0x01, 0x01};
  const auto len = static_cast<uint16_t>(raw.size());
  z.insert(z.end(), {static_cast<uint8_t>(len & 0xff), static_cast<uint8_t>(len >> 8),
                     static_cast<uint8_t>(~len & 0xff), static_cast<uint8_t>((~len >> 8) & 0xff)});
  z.insert(z.end(), raw.begin(), raw.end());
  uint32_t a = 1, b = 0;
  for (uint8_t byte : raw) {
    a = (a + byte) % 65521;
    b = (b + a) % 65521;
  }
  appendU32(z, (b << 16) | a);
  return z;
}

// A hand-made PNG: signature, IHDR (w, h, bit depth 8, colour type), optional PLTE, IDAT, IEND.
std::vector<uint8_t> handMadePng(uint32_t w, uint32_t h, uint8_t colour_type, int samples_per_px) {
  std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<uint8_t> ihdr;
  appendU32(ihdr, w);
  appendU32(ihdr, h);
  ihdr.insert(ihdr.end(), {8, colour_type, 0, 0, 0});
  appendChunk(out, "IHDR", ihdr);
  if (colour_type == png::kPalette) {
    appendChunk(out, "PLTE", {128, 128, 255, 255, 128, 128});
  }
  // Small images get real scanlines; huge claimed ones a token IDAT (never decoded).
  std::vector<uint8_t> raw;
  if (w * h <= 64) {
    for (uint32_t r = 0; r < h; ++r) {
      raw.push_back(0);
      raw.insert(raw.end(), w * static_cast<uint32_t>(samples_per_px), 0);
    }
  } else {
    raw = {0, 0, 0};
  }
  appendChunk(out, "IDAT", storedZlib(raw));
  appendChunk(out, "IEND", {});
  return out;
}

struct RoundTripCase {
  int bits;
  bool alpha;
  GreenConvention green;
};

// Readable test names: bits8_rgb_opengl, bits16_rgba_directx, ...
std::string caseName(const ::testing::TestParamInfo<RoundTripCase>& info) {
  const RoundTripCase& c = info.param;
  return "bits" + std::to_string(c.bits) + (c.alpha ? "_rgba" : "_rgb") +
         (c.green == GreenConvention::OpenGL ? "_opengl" : "_directx");
}

void PrintTo(const RoundTripCase& c, std::ostream* os) {
  *os << c.bits << " bit, " << (c.alpha ? "RGBA" : "RGB") << ", "
      << (c.green == GreenConvention::OpenGL ? "OpenGL" : "DirectX");
}

class PngRoundTrip : public ::testing::TestWithParam<RoundTripCase> {};

TEST_P(PngRoundTrip, SaveThenLoadIsWithinQuantisation) {
  const RoundTripCase c = GetParam();
  const NormalMap map = variedMap(7, 5);
  const std::string path = test::tempDir("png") + "/map.png";
  saveNormalMapPng(map, path, {c.bits, c.alpha, c.green});
  const NormalMap back = loadNormalMapPng(path, c.green);
  // Rounding costs at most 1/max per component; renormalising spreads it over the others.
  const double step = c.bits == 16 ? 1.0 / 65535.0 : 1.0 / 255.0;
  EXPECT_LE(maxDifference(map, back), 2.0 * step);
}

INSTANTIATE_TEST_SUITE_P(Formats, PngRoundTrip,
                         ::testing::Values(RoundTripCase{8, false, GreenConvention::OpenGL},
                                           RoundTripCase{8, true, GreenConvention::OpenGL},
                                           RoundTripCase{16, false, GreenConvention::OpenGL},
                                           RoundTripCase{16, true, GreenConvention::OpenGL},
                                           RoundTripCase{8, false, GreenConvention::DirectX},
                                           RoundTripCase{16, true, GreenConvention::DirectX}),
                         caseName);

TEST(PngIo, DirectXSavedLoadedAsOpenGLFlipsGreen) {
  const NormalMap map = variedMap(4, 3);
  const std::string path = test::tempDir("png") + "/dx.png";
  saveNormalMapPng(map, path, {16, false, GreenConvention::DirectX});
  const NormalMap back = loadNormalMapPng(path, GreenConvention::OpenGL);
  for (size_t k = 0; k < map.texels().size(); ++k) {
    const Vec3f& a = map.texels()[k];
    const Vec3f& b = back.texels()[k];
    EXPECT_TRUE(near(b.x(), a.x(), 0.0, 1e-4));
    EXPECT_TRUE(near(b.y(), -a.y(), 0.0, 1e-4));
    EXPECT_TRUE(near(b.z(), a.z(), 0.0, 1e-4));
  }
}

TEST(PngIo, TopPngRowIsLastMapRow) {
  // Write raw pixels: the first (top) PNG row is pure +x (255, 128, 128), the rest flat.
  const int w = 3, h = 4;
  std::vector<uint16_t> samples(static_cast<size_t>(w * h * 3));
  for (int k = 0; k < w * h; ++k) {
    const bool top = k < w;
    samples[3 * k + 0] = top ? 255 : 128;
    samples[3 * k + 1] = 128;
    samples[3 * k + 2] = top ? 128 : 255;
  }
  const std::string path = test::tempDir("png") + "/rows.png";
  png::write(path, w, h, 3, 8, samples);
  const NormalMap map = loadNormalMapPng(path);
  for (int i = 0; i < w; ++i) {
    EXPECT_GT(map.at(i, h - 1).x(), 0.99f);
    for (int j = 0; j < h - 1; ++j) EXPECT_GT(map.at(i, j).z(), 0.99f);
  }
  // Saving writes it back the same way round.
  saveNormalMapPng(map, path);
  EXPECT_GT(loadNormalMapPng(path).at(0, h - 1).x(), 0.99f);
}

TEST(PngIo, DecodedValuesFollowTwoRgbMinusOne) {
  // (255, 128, 128) -> (1, 1/255, 1/255) normalised; (128, 128, 255) -> ~ (0, 0, 1).
  const std::string path = test::tempDir("png") + "/values.png";
  png::write(path, 2, 1, 3, 8, {255, 128, 128, 64, 128, 255});
  const NormalMap map = loadNormalMapPng(path);
  const Vec3f expected = Vec3f(1.0f, 1.0f / 255.0f, 1.0f / 255.0f).normalized();
  EXPECT_TRUE(near(map.at(0, 0).x(), expected.x(), 0.0, 1e-6));
  const Vec3f tilted = Vec3f(2.0f * 64.0f / 255.0f - 1.0f, 1.0f / 255.0f, 1.0f).normalized();
  EXPECT_TRUE(near(map.at(1, 0).x(), tilted.x(), 0.0, 1e-6));
}

TEST(PngIo, TexelsThatAreNotNormalsReadFlatAndAreCounted) {
  // SPEC 10: mid grey (length 0.007), white (length 1.73) and a normal facing into the surface
  // (z < 0) are not normals; they read flat, are counted, and the caller warns about them.
  const std::string path = test::tempDir("png") + "/hygiene.png";
  png::write(path, 4, 1, 3, 8, {128, 128, 128, 255, 255, 255, 128, 128, 0, 200, 128, 220});
  NormalMapStats stats;
  const NormalMap map = loadNormalMapPng(path, GreenConvention::OpenGL, &stats);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(map.at(i, 0), Vec3f(0, 0, 1)) << i;
  EXPECT_GT(map.at(3, 0).x(), 0.5f);
  EXPECT_EQ(stats.texels, 4u);
  EXPECT_EQ(stats.invalid, 3u);
  EXPECT_DOUBLE_EQ(stats.invalidFraction(), 0.75);
  // Decoding prints nothing; the warning is one line naming the file and the share.
  testing::internal::CaptureStderr();
  loadNormalMapPng(path);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  Diagnostics diagnostics;
  warnInvalidTexels(path, stats, diagnostics);
  ASSERT_EQ(diagnostics.warnings().size(), 1u);
  EXPECT_EQ(diagnostics.warnings()[0],
            path + ": 75 % of texels are not unit normals; treated as flat");
  // A map whose texels are all normals gives no warning.
  warnInvalidTexels(path, NormalMapStats{4, 0, 8}, diagnostics);
  EXPECT_EQ(diagnostics.warnings().size(), 1u);
}

TEST(PngIo, DecodeFromMemoryAppliesScaleToXAndY) {
  // glTF normalTexture.scale: x and y scaled, then normalised.
  const std::string path = test::tempDir("png") + "/scaled.png";
  png::write(path, 1, 1, 3, 8, {200, 128, 220});
  std::ifstream in(path, std::ios::binary);
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                   std::istreambuf_iterator<char>()};
  const Vec3f m = decodeNormalMap(bytes, "scaled", GreenConvention::OpenGL, 2.0).at(0, 0);
  const Vec3f raw(2.0f * 200 / 255 - 1, 2.0f * 128 / 255 - 1, 2.0f * 220 / 255 - 1);
  EXPECT_TRUE(m.isApprox(Vec3f(2 * raw.x(), 2 * raw.y(), raw.z()).normalized(), 1e-6f));
  EXPECT_THROW(decodeNormalMap({1, 2, 3}, "junk"), Error);
}

TEST(PngIoErrors, MissingFile) {
  expectError([] { loadNormalMapPng("/nonexistent/dir/none.png"); },
              {"/nonexistent/dir/none.png", "cannot open"});
}

// Found by the generators fuzz target: a heightmap `file` naming a directory used to end the
// process with an uncaught stream exception.
TEST(PngIoErrors, DirectoryIsAnErrorNotACrash) {
  const std::string dir = test::tempDir("png");
  expectError([&] { loadNormalMapPng(dir); }, {dir, "is a directory"});
}

TEST(PngIoErrors, TruncatedFile) {
  const std::string dir = test::tempDir("png");
  saveNormalMapPng(variedMap(16, 16), dir + "/full.png");
  std::vector<uint8_t> bytes = png::readFile(dir + "/full.png");
  for (size_t keep : {size_t{4}, size_t{20}, bytes.size() / 2, bytes.size() - 3}) {
    writeBytes(dir + "/cut.png", std::vector<uint8_t>(bytes.begin(), bytes.begin() + keep));
    expectError([&] { loadNormalMapPng(dir + "/cut.png"); }, {dir + "/cut.png"});
  }
  writeBytes(dir + "/cut.png",
             std::vector<uint8_t>(bytes.begin(), bytes.begin() + bytes.size() / 2));
  expectError([&] { loadNormalMapPng(dir + "/cut.png"); }, {"truncated"});
}

TEST(PngIoErrors, CorruptBytes) {
  const std::string dir = test::tempDir("png");
  saveNormalMapPng(variedMap(16, 16), dir + "/ok.png");
  std::vector<uint8_t> bytes = png::readFile(dir + "/ok.png");
  // Flip bytes inside IDAT: the chunk CRC no longer matches.
  bytes[bytes.size() / 2] ^= 0x5a;
  writeBytes(dir + "/bad.png", bytes);
  expectError([&] { loadNormalMapPng(dir + "/bad.png"); }, {dir + "/bad.png", "corrupt", "IDAT"});
  // Not a PNG at all.
  writeBytes(dir + "/text.png", {'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o', 'r', 'l', 'd'});
  expectError([&] { loadNormalMapPng(dir + "/text.png"); }, {"text.png", "not a PNG"});
  writeBytes(dir + "/empty.png", {});
  expectError([&] { loadNormalMapPng(dir + "/empty.png"); }, {"empty.png", "empty"});
}

TEST(PngIoErrors, CorruptImageDataWithValidCrc) {
  // A well-formed chunk sequence whose IDAT is not a zlib stream: stb's decoder rejects it.
  const std::string dir = test::tempDir("png");
  std::vector<uint8_t> bytes = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<uint8_t> ihdr;
  appendU32(ihdr, 2);
  appendU32(ihdr, 2);
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});
  appendChunk(bytes, "IHDR", ihdr);
  appendChunk(bytes, "IDAT", {1, 2, 3, 4, 5, 6, 7});
  appendChunk(bytes, "IEND", {});
  writeBytes(dir + "/garbage.png", bytes);
  expectError([&] { loadNormalMapPng(dir + "/garbage.png"); }, {"garbage.png", "corrupt"});
}

TEST(PngIoErrors, GrayscaleRejected) {
  const std::string dir = test::tempDir("png");
  png::write(dir + "/grey.png", 2, 2, 1, 8, {0, 50, 100, 200});
  expectError([&] { loadNormalMapPng(dir + "/grey.png"); }, {"grey.png", "grayscale"});
  png::write(dir + "/grey_alpha.png", 1, 1, 2, 16, {100, 65535});
  expectError([&] { loadNormalMapPng(dir + "/grey_alpha.png"); }, {"grey_alpha.png", "grayscale"});
}

TEST(PngIoErrors, PaletteRejected) {
  const std::string dir = test::tempDir("png");
  writeBytes(dir + "/palette.png", handMadePng(2, 2, png::kPalette, 1));
  // The file itself is valid: stb would decode it (expanding the palette) ...
  const png::Image image = png::decode(png::readFile(dir + "/palette.png"), "p", 16, 3);
  EXPECT_EQ(image.header.colour_type, png::kPalette);
  // ... but a normal map must not come from it.
  expectError([&] { loadNormalMapPng(dir + "/palette.png"); }, {"palette.png", "palette"});
}

TEST(PngIoErrors, ZeroSized) {
  const std::string dir = test::tempDir("png");
  writeBytes(dir + "/zero.png", handMadePng(0, 4, png::kRgb, 3));
  expectError([&] { loadNormalMapPng(dir + "/zero.png"); }, {"zero.png", "zero-sized"});
}

TEST(PngIoErrors, EnormousRejectedFromHeader) {
  // 100000 x 100000 RGB would need 30 GB; the header check must refuse before decoding.
  const std::string dir = test::tempDir("png");
  writeBytes(dir + "/huge.png", handMadePng(100000, 100000, png::kRgb, 3));
  expectError([&] { loadNormalMapPng(dir + "/huge.png"); },
              {"huge.png", "100000 x 100000", "exceeds", std::to_string(kMaxTextureSize)});
}

TEST(PngIoErrors, BadSaveArguments) {
  const std::string dir = test::tempDir("png");
  expectError([&] { saveNormalMapPng(NormalMap(), dir + "/e.png"); }, {"e.png", "empty"});
  expectError([&] { saveNormalMapPng(NormalMap(2, 2), dir + "/b.png", {12}); }, {"b.png", "bits"});
  expectError([&] { saveNormalMapPng(NormalMap(2, 2), "/nonexistent/dir/x.png"); },
              {"/nonexistent/dir/x.png", "cannot write"});
}

}  // namespace
}  // namespace asperity
