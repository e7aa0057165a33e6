// GPU resources of the OpenGL patch sampler: the atlas (coverage and coefficient targets, depth,
// one frame buffer per sub-pass of at most 7 direction groups), the read-back of each pass's
// sums (made on the GPU) with its fence, the programs per group count, and normal-map / mask
// textures cached per object.
#pragma once

#include <epoxy/gl.h>

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "asperity/geometry/surface.hpp"
#include "asperity/sampler/friction_provider.hpp"
#include "asperity/texture/height_map.hpp"
#include "gl/objects.hpp"
#include "gl/shader.hpp"

namespace asperity::glpatch {

inline constexpr int kMaxGroupsPerPass = 7;  // colour attachment 0 is the coverage target
// Direction groups summed per dispatch: their targets and the coverage fit the 16 texture
// units that every OpenGL 4.3 compute stage has.
inline constexpr int kMaxGroupsPerSum = 8;

class Programs;

class Atlas {
 public:
  // (Re)allocates for this size, packing and number of direction groups (N / 4).
  void ensure(int size, bool float_targets, int groups, int max_draw_buffers);

  int size() const { return size_; }
  int groups() const { return groups_; }
  int groupsPerPass() const { return groups_per_pass_; }
  int subPasses() const { return (groups_ + groups_per_pass_ - 1) / groups_per_pass_; }
  bool floatTargets() const { return float_targets_; }
  // Binds sub-pass s's frame buffer with its draw buffers and clears it.
  void beginSubPass(int s);
  GLuint coverageTexture() const { return *coverage_; }
  GLuint muTexture(int g) const { return mu_[static_cast<size_t>(g)]; }

 private:
  int size_ = 0;
  bool float_targets_ = false;
  int groups_ = 0;
  int groups_per_pass_ = 1;
  std::unique_ptr<gl::Texture> coverage_;
  std::vector<gl::Texture> mu_;
  std::unique_ptr<gl::Renderbuffer> depth_;
  std::vector<gl::Framebuffer> framebuffers_;
};

// The atlas of a pass whose fragments come back whole (the program of 0 groups): per pixel
// (g_t, g_b, height, depth key) in RGBA32F, a depth key of kNoFragment where nothing was drawn.
class FragmentAtlas {
 public:
  static constexpr float kNoFragment = -3.0e38f;
  void ensure(int size);
  int size() const { return size_; }
  // Binds its frame buffer and clears it.
  void begin();
  // Rows [0, rows) of the atlas as rendered, 4 floats a pixel, into `out`.
  void read(int rows, std::vector<float>& out) const;

 private:
  int size_ = 0;
  std::unique_ptr<gl::Texture> fragments_;
  std::unique_ptr<gl::Renderbuffer> depth_;
  std::unique_ptr<gl::Framebuffer> framebuffer_;
};

// What one pass sums on the GPU (patch_average.comp.glsl).
struct SumLayout {
  int contacts = 0;    // tiles 2c and 2c + 1 of the atlas, c < contacts
  int resolution = 0;  // R
  int directions = 0;  // N
  float scale = 1.0f;  // mu per unit of the targets (mu_max for RGBA8)
  // Floats per lane: |P| of its rows, N sums of surface A, N of surface B; kSumLanes lanes a
  // contact.
  size_t stride() const { return 1 + 2 * static_cast<size_t>(directions); }
};
inline constexpr int kSumLanes = 16;  // patch_average.comp.glsl's local size

// One pass's sums, made on the GPU into a storage buffer, and the fence that says they are
// written: per contact kSumLanes x (N + N + 1) floats come back instead of two tiles of pixels.
class Readback {
 public:
  // Dispatches the sums over the atlas as rendered, then the fence.
  void start(const Atlas& atlas, Programs& programs, const SumLayout& layout);
  // Waits for the fence and maps the sums (kSumLanes x SumLayout::stride() floats a contact);
  // unmap() releases them.
  void map();
  void unmap();
  bool pending() const { return fence_ != nullptr; }
  const float* sums() const { return sums_; }
  ~Readback();

 private:
  std::unique_ptr<gl::Buffer> buffer_;
  size_t capacity_ = 0, bytes_ = 0;
  GLsync fence_ = nullptr;
  const float* sums_ = nullptr;
};

// Textures uploaded once per NormalMap / GainMask (keyed by address, kept alive while cached).
class TextureCache {
 public:
  // Each texture filtered as `reading` asks: GL_NEAREST (one texel a facet) or GL_LINEAR.
  GLuint normalMap(const std::shared_ptr<const NormalMap>& map, TexelReading reading);
  GLuint mask(const std::shared_ptr<const GainMask>& mask, TexelReading reading);
  // A surface's heights (bilinear, as the CPU sampler reads them); the caller keeps `heights`
  // alive while the cache lives.
  GLuint heights(const HeightMap& heights);

 private:
  struct Entry {
    std::shared_ptr<const void> keep_alive;
    gl::Texture texture;
  };
  // The texture of one map under one reading: a surface read both ways (two worlds on one
  // context) keeps two textures rather than resetting its filter at every draw.
  std::map<std::pair<const void*, TexelReading>, Entry> entries_;
};

// The patch programs, one per direction-group count (1..7), and the summing programs, one per
// group count of a dispatch (1..8), compiled on first use.
class Programs {
 public:
  const gl::Program& get(int groups);
  const gl::Program& sum(int groups);

 private:
  std::map<int, gl::Program> programs_, sums_;
};

}  // namespace asperity::glpatch
