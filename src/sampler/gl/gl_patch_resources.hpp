// GPU resources of the OpenGL patch sampler: the atlas (coverage and coefficient targets, depth,
// one frame buffer per sub-pass of at most 7 direction groups), the read-back pixel buffers with
// their fence, the programs per group count, and normal-map / mask textures cached per object.
#pragma once

#include <epoxy/gl.h>

#include <map>
#include <memory>
#include <vector>

#include "asperity/geometry/surface.hpp"
#include "gl/objects.hpp"
#include "gl/shader.hpp"

namespace asperity::glpatch {

inline constexpr int kMaxGroupsPerPass = 7;  // colour attachment 0 is the coverage target

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
  // The frame buffer and attachment holding group g (or the coverage when g < 0).
  GLuint framebufferOf(int g) const;
  GLenum attachmentOf(int g) const;

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

// Pixel buffers for one pass's read-back, and the fence that says they are filled.
class Readback {
 public:
  // Issues asynchronous reads of `rows` rows of every target into the buffers, then the fence.
  void start(const Atlas& atlas, int rows);
  // Waits for the fence and maps the buffers (coverage, then groups); unmap() releases them.
  void map();
  void unmap();
  bool pending() const { return fence_ != nullptr; }
  const uint8_t* coverage() const { return coverage_ptr_; }
  const void* group(int g) const { return group_ptrs_[static_cast<size_t>(g)]; }
  ~Readback();

 private:
  std::unique_ptr<gl::Buffer> coverage_;
  std::vector<gl::Buffer> groups_;
  size_t coverage_bytes_ = 0, group_bytes_ = 0, capacity_ = 0;
  GLsync fence_ = nullptr;
  const uint8_t* coverage_ptr_ = nullptr;
  std::vector<const void*> group_ptrs_;
};

// Textures uploaded once per NormalMap / GainMask (keyed by address, kept alive while cached).
class TextureCache {
 public:
  GLuint normalMap(const std::shared_ptr<const NormalMap>& map);
  GLuint mask(const std::shared_ptr<const GainMask>& mask);

 private:
  struct Entry {
    std::shared_ptr<const void> keep_alive;
    gl::Texture texture;
  };
  std::map<const void*, Entry> entries_;
};

// The patch programs, one per direction-group count (1..7), compiled on first use.
class Programs {
 public:
  const gl::Program& get(int groups);

 private:
  std::map<int, gl::Program> programs_;
};

}  // namespace asperity::glpatch
