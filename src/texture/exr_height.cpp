// OpenEXR height maps through Debian's libopenexr-dev (ASPERITY_HAVE_OPENEXR is defined for this
// file alone when CMake finds it, so the rest of the library compiles the same either way).
#include "texture/exr_height.hpp"

#include "asperity/error.hpp"
#include "asperity/texture/png_io.hpp"

#ifdef ASPERITY_HAVE_OPENEXR
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>
#endif

namespace asperity::exr {

#ifdef ASPERITY_HAVE_OPENEXR

namespace {

// The channel that holds the heights, by name, or the only one.
std::string heightChannel(const Imf::ChannelList& channels, const std::string& path) {
  for (const char* name : {"height", "Z", "Y", "R"})
    if (channels.findChannel(name) != nullptr) return name;
  auto it = channels.begin();
  if (it != channels.end()) {
    const std::string only = it.name();
    if (++it == channels.end()) return only;
  }
  throw Error("OpenEXR file '" + path +
              "': no channel named height, Z, Y or R, and more than one channel");
}

// The data window's size, checked against the cap of PNG maps before anything is allocated (a
// header alone may claim 40000 x 40000).
void checkSize(const Imath::Box2i& window, const std::string& path) {
  const int64_t w = int64_t{window.max.x} - window.min.x + 1;
  const int64_t h = int64_t{window.max.y} - window.min.y + 1;
  if (w < 1 || h < 1 || w > kMaxTextureSize || h > kMaxTextureSize) {
    throw Error("OpenEXR file '" + path + "': data window " + std::to_string(w) + " x " +
                std::to_string(h) + "; height maps are 1 to " + std::to_string(kMaxTextureSize) +
                " texels a side");
  }
}

// Heights must be numbers: one NaN or infinity would make every statistic of the map one too.
void checkFinite(const HeightMap& map, const std::string& path) {
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i)
      if (!std::isfinite(map.at(i, j)))
        throw Error("OpenEXR file '" + path + "': the texel at column " + std::to_string(i) +
                    ", row " + std::to_string(map.height - 1 - j) + " (from the top) is " +
                    std::to_string(map.at(i, j)) + " once scaled; heights must be finite");
}

}  // namespace

bool available() {
  return true;
}

HeightMap load(const std::string& path, double scale) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    checkSize(window, path);
    const int w = window.max.x - window.min.x + 1;
    const int h = window.max.y - window.min.y + 1;
    const std::string channel = heightChannel(file.header().channels(), path);
    std::vector<float> pixels(static_cast<size_t>(w) * static_cast<size_t>(h));
    // The slice's base points at pixel (0, 0) of the data window's coordinates.
    const ptrdiff_t origin = -static_cast<ptrdiff_t>(window.min.x) -
                             static_cast<ptrdiff_t>(window.min.y) * static_cast<ptrdiff_t>(w);
    Imf::FrameBuffer frame;
    frame.insert(channel, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data() + origin),
                                     sizeof(float), sizeof(float) * static_cast<size_t>(w)));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    HeightMap map(w, h);
    for (int r = 0; r < h; ++r)
      for (int i = 0; i < w; ++i)
        map.at(i, h - 1 - r) =
            static_cast<float>(scale * pixels[static_cast<size_t>(r) * static_cast<size_t>(w) + i]);
    checkFinite(map, path);
    return map;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error("OpenEXR file '" + path + "': " + e.what());
  }
}

void save(const HeightMap& map, const std::string& path) {
  try {
    std::vector<float> pixels(map.values.size());
    for (int r = 0; r < map.height; ++r)
      for (int i = 0; i < map.width; ++i)
        pixels[static_cast<size_t>(r) * static_cast<size_t>(map.width) + i] =
            map.at(i, map.height - 1 - r);
    Imf::Header header(map.width, map.height);
    header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(path.c_str(), header);
    Imf::FrameBuffer frame;
    frame.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data()), sizeof(float),
                                 sizeof(float) * static_cast<size_t>(map.width)));
    file.setFrameBuffer(frame);
    file.writePixels(map.height);
  } catch (const std::exception& e) {
    throw Error("OpenEXR file '" + path + "': " + e.what());
  }
}

#else

bool available() {
  return false;
}

HeightMap load(const std::string& path, double) {
  throw Error("OpenEXR file '" + path +
              "': this build has no OpenEXR support (install libopenexr-dev and reconfigure)");
}

void save(const HeightMap&, const std::string& path) {
  throw Error("OpenEXR file '" + path +
              "': this build has no OpenEXR support (install libopenexr-dev and reconfigure)");
}

#endif

}  // namespace asperity::exr
