// GPU resources of the OpenGL patch sampler (gl_patch_resources.hpp).
#include "sampler/gl/gl_patch_resources.hpp"

#include <algorithm>
#include <string>

#include "asperity/error.hpp"
#include "sampler/gl/shaders.hpp"

namespace asperity::glpatch {

namespace {

// A 2D texture with no mipmaps and the given wrap and filter.
void setupTexture(GLuint texture, GLint wrap, GLint filter) {
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
}

GLint filterOf(TexelReading reading) {
  return reading == TexelReading::Bilinear ? GL_LINEAR : GL_NEAREST;
}

}  // namespace

void Atlas::ensure(int size, bool float_targets, int groups, int max_draw_buffers) {
  if (size == size_ && float_targets == float_targets_ && groups == groups_) return;
  size_ = size;
  float_targets_ = float_targets;
  groups_ = groups;
  groups_per_pass_ = std::clamp(max_draw_buffers - 1, 1, kMaxGroupsPerPass);
  // Coverage (R8), coefficients (RGBA8 or RGBA32F) and a shared depth buffer.
  coverage_ = std::make_unique<gl::Texture>();
  setupTexture(*coverage_, GL_CLAMP_TO_EDGE, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, size, size, 0, GL_RED, GL_UNSIGNED_BYTE, nullptr);
  mu_.clear();
  mu_.resize(static_cast<size_t>(groups));
  for (gl::Texture& t : mu_) {
    setupTexture(t, GL_CLAMP_TO_EDGE, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, float_targets ? GL_RGBA32F : GL_RGBA8, size, size, 0, GL_RGBA,
                 float_targets ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr);
  }
  depth_ = std::make_unique<gl::Renderbuffer>();
  glBindRenderbuffer(GL_RENDERBUFFER, *depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, size, size);
  // One frame buffer per sub-pass: coverage at attachment 0, its groups after it.
  framebuffers_.clear();
  framebuffers_.resize(static_cast<size_t>(subPasses()));
  for (int s = 0; s < subPasses(); ++s) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[static_cast<size_t>(s)]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *coverage_, 0);
    const int first = s * groups_per_pass_;
    const int count = std::min(groups_per_pass_, groups - first);
    for (int g = 0; g < count; ++g) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, static_cast<GLenum>(GL_COLOR_ATTACHMENT1 + g),
                             GL_TEXTURE_2D, mu_[static_cast<size_t>(first + g)], 0);
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, *depth_);
    gl::checkFramebufferComplete("gl sampler atlas");
  }
  gl::checkGlError("gl sampler atlas allocation");
}

void Atlas::beginSubPass(int s) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[static_cast<size_t>(s)]);
  const int count = std::min(groups_per_pass_, groups_ - s * groups_per_pass_);
  GLenum buffers[kMaxGroupsPerPass + 1];
  for (int k = 0; k <= count; ++k) buffers[k] = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + k);
  glDrawBuffers(count + 1, buffers);
  // Everything starts uncovered, zero and at the far plane.
  glViewport(0, 0, size_, size_);
  const GLfloat zero[4] = {0, 0, 0, 0};
  for (int k = 0; k <= count; ++k) glClearBufferfv(GL_COLOR, k, zero);
  const GLfloat far = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far);
}

void FragmentAtlas::ensure(int size) {
  if (size == size_) return;
  size_ = size;
  fragments_ = std::make_unique<gl::Texture>();
  setupTexture(*fragments_, GL_CLAMP_TO_EDGE, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size, size, 0, GL_RGBA, GL_FLOAT, nullptr);
  depth_ = std::make_unique<gl::Renderbuffer>();
  glBindRenderbuffer(GL_RENDERBUFFER, *depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, size, size);
  framebuffer_ = std::make_unique<gl::Framebuffer>();
  glBindFramebuffer(GL_FRAMEBUFFER, *framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *fragments_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, *depth_);
  gl::checkFramebufferComplete("gl sampler fragment atlas");
  gl::checkGlError("gl sampler fragment atlas allocation");
}

void FragmentAtlas::begin() {
  glBindFramebuffer(GL_FRAMEBUFFER, *framebuffer_);
  const GLenum buffer = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &buffer);
  glViewport(0, 0, size_, size_);
  const GLfloat none[4] = {0, 0, 0, kNoFragment};
  glClearBufferfv(GL_COLOR, 0, none);
  const GLfloat far = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far);
}

void FragmentAtlas::read(int rows, std::vector<float>& out) const {
  out.resize(static_cast<size_t>(size_) * static_cast<size_t>(rows) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, *framebuffer_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, size_, rows, GL_RGBA, GL_FLOAT, out.data());
  gl::checkGlError("gl sampler fragment read-back");
}

void Readback::start(const Atlas& atlas, Programs& programs, const SumLayout& layout) {
  bytes_ = static_cast<size_t>(layout.contacts) * kSumLanes * layout.stride() * sizeof(float);
  if (!buffer_ || capacity_ < bytes_) {
    buffer_ = std::make_unique<gl::Buffer>();
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, *buffer_);
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes_), nullptr,
                 GL_STREAM_READ);
    capacity_ = bytes_;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, *buffer_);
  // Unit 0 the coverage, units 1.. this dispatch's coefficient targets.
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, atlas.coverageTexture());
  for (int first = 0; first < atlas.groups(); first += kMaxGroupsPerSum) {
    const int groups = std::min(kMaxGroupsPerSum, atlas.groups() - first);
    const gl::Program& program = programs.sum(groups);
    program.use();
    for (int g = 0; g < groups; ++g) {
      glActiveTexture(static_cast<GLenum>(GL_TEXTURE1 + g));
      glBindTexture(GL_TEXTURE_2D, atlas.muTexture(first + g));
    }
    program.set("u_resolution", layout.resolution);
    program.set("u_per_row", atlas.size() / layout.resolution);
    program.set("u_directions", layout.directions);
    program.set("u_first_group", first);
    program.set("u_scale", layout.scale);
    glDispatchCompute(static_cast<GLuint>(layout.contacts), 1, 1);
  }
  glActiveTexture(GL_TEXTURE0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  // The shader's writes are to be seen through a mapping.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  gl::checkGlError("gl sampler sums");
}

void Readback::map() {
  // Wait for this pass's sums (flushing once), then map them for reading.
  const GLenum status = glClientWaitSync(fence_, GL_SYNC_FLUSH_COMMANDS_BIT, 60'000'000'000ull);
  glDeleteSync(fence_);
  fence_ = nullptr;
  if (status == GL_TIMEOUT_EXPIRED || status == GL_WAIT_FAILED) {
    throw Error("gl sampler: read-back fence did not signal");
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, *buffer_);
  sums_ = static_cast<const float*>(glMapBufferRange(
      GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes_), GL_MAP_READ_BIT));
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  if (sums_ == nullptr) throw Error("gl sampler: could not map the sums");
}

void Readback::unmap() {
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, *buffer_);
  glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  sums_ = nullptr;
}

Readback::~Readback() {
  if (fence_ != nullptr) glDeleteSync(fence_);
}

GLuint TextureCache::normalMap(const std::shared_ptr<const NormalMap>& map, TexelReading reading) {
  auto it = entries_.find({map.get(), reading});
  if (it != entries_.end()) return it->second.texture;
  // First use: the unit vectors as RGB32F (rows bottom-up, as NormalMap stores them).
  Entry& e = entries_[{map.get(), reading}];
  e.keep_alive = map;
  setupTexture(e.texture, GL_REPEAT, filterOf(reading));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, map->width(), map->height(), 0, GL_RGB, GL_FLOAT,
               map->texels().data());
  gl::checkGlError("gl sampler normal map upload");
  return e.texture;
}

GLuint TextureCache::mask(const std::shared_ptr<const GainMask>& mask, TexelReading reading) {
  auto it = entries_.find({mask.get(), reading});
  if (it != entries_.end()) return it->second.texture;
  Entry& e = entries_[{mask.get(), reading}];
  e.keep_alive = mask;
  setupTexture(e.texture, GL_REPEAT, filterOf(reading));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, mask->width, mask->height, 0, GL_RED, GL_FLOAT,
               mask->values.data());
  gl::checkGlError("gl sampler mask upload");
  return e.texture;
}

GLuint TextureCache::heights(const HeightMap& heights) {
  auto it = entries_.find({&heights, TexelReading::Bilinear});
  if (it != entries_.end()) return it->second.texture;
  Entry& e = entries_[{&heights, TexelReading::Bilinear}];
  setupTexture(e.texture, GL_REPEAT, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, heights.width, heights.height, 0, GL_RED, GL_FLOAT,
               heights.values.data());
  gl::checkGlError("gl sampler height upload");
  return e.texture;
}

const gl::Program& Programs::get(int groups) {
  auto it = programs_.find(groups);
  if (it != programs_.end()) return it->second;
  // The fragment stage: version, group count, the friction model, then the patch shader.
  const std::string version = "#version 430 core\n";
  const std::string vertex = version + std::string(gl_shaders::patch_vert);
  const std::string fragment = version + "#define GROUPS " + std::to_string(groups) + "\n" +
                               std::string(gl_shaders::ploughing) +
                               std::string(gl_shaders::patch_frag);
  gl::Program program("gl sampler patch (" + std::to_string(groups) + " groups)",
                      {{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}});
  return programs_.emplace(groups, std::move(program)).first->second;
}

const gl::Program& Programs::sum(int groups) {
  auto it = sums_.find(groups);
  if (it != sums_.end()) return it->second;
  const std::string source = "#version 430 core\n#define GROUPS " + std::to_string(groups) + "\n" +
                             std::string(gl_shaders::patch_average_comp);
  gl::Program program("gl sampler sums (" + std::to_string(groups) + " groups)",
                      {{GL_COMPUTE_SHADER, source}});
  // Its texture units, fixed: the coverage on 0, the groups' targets on 1.. (Readback::start).
  program.use();
  program.set("u_coverage", 0);
  for (int g = 0; g < groups; ++g) program.set(("u_mu[" + std::to_string(g) + "]").c_str(), 1 + g);
  return sums_.emplace(groups, std::move(program)).first->second;
}

}  // namespace asperity::glpatch
