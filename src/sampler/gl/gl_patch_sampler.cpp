// The OpenGL patch sampler (gl_patch_sampler.hpp): per pass, collect both surfaces' triangles of
// every contact into one vertex buffer, render each surface into its tile (Eq. 5 in the fragment
// shader), sum each contact's tiles on the GPU (Eq. 8, a compute shader), read the sums back
// asynchronously and finish each contact on the CPU (Eq. 7). Each vertex carries its tile, so
// one draw per material renders every contact: under llvmpipe the state changes of a draw per
// surface cost twice the drawing itself.
#include "asperity/sampler/gl_patch_sampler.hpp"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "asperity/error.hpp"
#include "asperity/friction/directions.hpp"
#include "asperity/gl/context.hpp"
#include "parallel/thread_pool.hpp"
#include "sampler/gl/gl_patch_fragments.hpp"
#include "sampler/gl/gl_patch_resources.hpp"
#include "sampler/gl/gl_saved_state.hpp"
#include "sampler/models/friction_models.hpp"
#include "sampler/patch_common.hpp"
#include "sampler/patch_heights.hpp"
#include "sampler/patch_triangles.hpp"

namespace asperity {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// A run of triangles of one surface of one contact with one material. The surface's textures
// become GL names (map, mask) on the calling thread, after the triangles are collected.
struct Draw {
  const Surface* surface = nullptr;
  GLuint map = 0, mask = 0, heights = 0;
  GLint first = 0;
  GLsizei count = 0;
};

// Per vertex beside PatchVertex: its tile's lower-left corner (atlas pixels), the side (+1
// surface B, -1 surface A) and the contact's half depth (patch.vert.glsl's a_tile).
struct TileVertex {
  float origin[2];
  float side;
  float half_depth;
};

// The draws of one material, rendered by one glMultiDrawArrays.
struct Batch {
  GLuint map = 0, mask = 0, heights = 0;
  size_t first = 0, count = 0;  // into Impl::firsts and Impl::counts
};

// What the averaging needs per contact of a pass.
struct PassContact {
  Contact* contact = nullptr;
  PatchGains gains;
  const models::FrictionModelVariant* model = nullptr;
  std::array<const Surface*, 2> surfaces{};  // each side's first shape's (ModelInputs)
  std::array<int, 2> shapes{};
};

// The triangles of a run of a pass's contacts, collected by one thread: its draws' firsts count
// from the chunk's own first vertex until the chunks are joined in contact order.
struct Chunk {
  std::vector<patch::PatchVertex> vertices;
  std::vector<TileVertex> tiles;
  std::vector<Draw> draws;
  patch::GeometryScratch scratch;
  size_t base = 0;  // the chunk's first vertex in the pass's buffers
};
// Contacts per chunk: enough work to pay for a task, few enough to spread a pass.
constexpr size_t kChunkContacts = 32;

}  // namespace

struct GlPatchSampler::Impl {
  GlSamplerOptions options;
  const ThreadPool* pool = nullptr;        // collects triangles, finishes sums (setThreadPool)
  std::unique_ptr<gl::GlContext> context;  // declared first: destroyed last
  glpatch::Atlas atlas;
  std::array<glpatch::Readback, 2> readbacks;
  glpatch::FragmentAtlas fragment_atlas;  // passes whose fragments come back whole
  patch::HeightCache heights;             // surface heights, for models that read them
  std::vector<float> fragment_pixels;     // a fragment pass's read-back
  glpatch::FragmentReduction reduction;   // its contacts' models, run here
  // This call's contacts by their model's needs: summed on the device, or read back whole.
  std::vector<Contact*> summed, whole;
  std::vector<const models::FrictionModelVariant*> whole_models;
  std::array<std::vector<PassContact>, 2> pass_contacts;
  glpatch::TextureCache textures;
  glpatch::Programs programs;
  std::unique_ptr<gl::VertexArray> vao;
  std::unique_ptr<gl::Buffer> vbo, tile_vbo;
  patch::MeshCache meshes;
  std::vector<Chunk> chunks;  // this pass's triangles, chunk_count of them in use
  size_t chunk_count = 0, vertex_count = 0;
  std::vector<Draw> draws;
  // The draws grouped by material (batch), each batch's runs in firsts and counts.
  std::vector<size_t> order;
  std::vector<Batch> batches;
  std::vector<GLint> firsts;
  std::vector<GLsizei> counts;
  int max_draw_buffers = 8;
  double patch_ms = 0.0, averaging_ms = 0.0;
  int passes = 0;
  // A call between startCoefficients and finishCoefficients.
  struct InFlight {
    bool active = false;
    glpatch::SavedState saved;
    std::span<const Body> bodies;
    std::span<Contact> contacts;
    FrictionSettings settings;
    double busy_ms = 0.0;  // spent in start
  } call;

  void setupVertexArray();
  // Drops a call that was started and never finished (its caller threw in between): its
  // reads are waited for and discarded, the caller's GL state restored.
  void abandon();
  // The triangles and draws of a pass; `fragments`: with the height textures of its surfaces.
  void collect(std::span<const Body> bodies, std::span<Contact* const> contacts,
               const FrictionSettings& settings, std::vector<PassContact>& out,
               bool fragments = false);
  void collectChunk(std::span<const Body> bodies, std::span<Contact* const> contacts,
                    size_t first_contact, const FrictionSettings& settings, Chunk& chunk,
                    std::span<PassContact> out);
  void upload(GLuint buffer, size_t vertex_size,
              const std::function<const void*(const Chunk&)>& data) const;
  void batchByMaterial();
  void setPatchUniforms(const gl::Program& program, const FrictionSettings& settings) const;
  // This call's contacts into summed and whole (with their models), by what their model needs.
  template <class ModelOf>
  void splitByModel(std::span<Contact* const> contacts, const ModelOf& model_of) {
    summed.clear();
    whole.clear();
    whole_models.clear();
    for (Contact* c : contacts) {
      const models::FrictionModelVariant& model = model_of(*c);
      if (model.finish_sums != nullptr) {
        summed.push_back(c);
      } else {
        whole.push_back(c);
        whole_models.push_back(&model);
      }
    }
  }
  // A pass's upload and GL state before its draws, and the state after them.
  void beginDraw();
  void endDraw(const char* what);
  void drawBatches(const gl::Program& program);
  void render(const FrictionSettings& settings);
  void average(int slot, const FrictionSettings& settings);
  // The contacts whose model reads their fragments whole: rendered, read back and reduced on
  // this thread, pass after pass.
  void sampleFragments(std::span<const Body> bodies, std::span<Contact* const> contacts,
                       std::span<const models::FrictionModelVariant* const> contact_models,
                       const FrictionSettings& settings, double dt);
};

void GlPatchSampler::Impl::setupVertexArray() {
  // Interleaved PatchVertex: position, uv, tangent, bitangent, normal, the three edge tests;
  // then TileVertex from its own buffer.
  vao = std::make_unique<gl::VertexArray>();
  vbo = std::make_unique<gl::Buffer>();
  tile_vbo = std::make_unique<gl::Buffer>();
  glBindVertexArray(*vao);
  glBindBuffer(GL_ARRAY_BUFFER, *vbo);
  const auto stride = static_cast<GLsizei>(sizeof(patch::PatchVertex));
  const struct {
    GLuint index;
    GLint size;
    size_t offset;
  } attributes[] = {{0, 3, offsetof(patch::PatchVertex, p)},
                    {1, 2, offsetof(patch::PatchVertex, uv)},
                    {2, 3, offsetof(patch::PatchVertex, t)},
                    {3, 3, offsetof(patch::PatchVertex, b)},
                    {4, 3, offsetof(patch::PatchVertex, n)},
                    {5, 4, offsetof(patch::PatchVertex, edges)},
                    {6, 4, offsetof(patch::PatchVertex, edges) + 4 * sizeof(float)},
                    {7, 4, offsetof(patch::PatchVertex, edges) + 8 * sizeof(float)}};
  for (const auto& a : attributes) {
    glEnableVertexAttribArray(a.index);
    glVertexAttribPointer(a.index, a.size, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(a.offset));
  }
  glBindBuffer(GL_ARRAY_BUFFER, *tile_vbo);
  glEnableVertexAttribArray(8);
  glVertexAttribPointer(8, 4, GL_FLOAT, GL_FALSE, sizeof(TileVertex), nullptr);
  glBindVertexArray(0);
}

void GlPatchSampler::Impl::collect(std::span<const Body> bodies, std::span<Contact* const> contacts,
                                   const FrictionSettings& settings, std::vector<PassContact>& out,
                                   bool fragments) {
  // The triangles of runs of contacts on the pool (the meshes they look up built first, here),
  // then joined in contact order: the same buffer and draws as one thread makes.
  if (pool) {
    for (const Contact* c : contacts) patch::prepareMeshes(meshes, bodies, *c, true);
  }
  chunk_count = (contacts.size() + kChunkContacts - 1) / kChunkContacts;
  if (chunks.size() < chunk_count) chunks.resize(chunk_count);
  out.resize(contacts.size());
  forEachOn(pool, chunk_count, 1, [&](size_t k) {
    const size_t first = k * kChunkContacts;
    const size_t count = std::min(kChunkContacts, contacts.size() - first);
    collectChunk(bodies, contacts.subspan(first, count), first, settings, chunks[k],
                 std::span(out).subspan(first, count));
  });
  draws.clear();
  vertex_count = 0;
  for (size_t k = 0; k < chunk_count; ++k) {
    Chunk& chunk = chunks[k];
    chunk.base = vertex_count;
    vertex_count += chunk.vertices.size();
    for (Draw d : chunk.draws) {
      const auto& map = d.surface->normal_map;
      d.map = map && !map->empty() ? textures.normalMap(map, settings.texel_reading) : 0;
      d.mask = d.surface->mask ? textures.mask(d.surface->mask, settings.texel_reading) : 0;
      const HeightMap* h = fragments && map ? heights.find(map.get()) : nullptr;
      d.heights = h != nullptr ? textures.heights(*h) : 0;
      d.first += static_cast<GLint>(chunk.base);
      draws.push_back(d);
    }
  }
}

void GlPatchSampler::Impl::collectChunk(std::span<const Body> bodies,
                                        std::span<Contact* const> contacts, size_t first_contact,
                                        const FrictionSettings& settings, Chunk& chunk,
                                        std::span<PassContact> out) {
  chunk.vertices.clear();
  chunk.tiles.clear();
  chunk.draws.clear();
  const int r = settings.patch_resolution, per_row = atlas.size() / r;
  // Contact c of the pass: A in tile 2c, B in tile 2c + 1; one draw per shape with triangles.
  for (size_t i = 0; i < contacts.size(); ++i) {
    Contact& contact = *contacts[i];
    const size_t c = first_contact + i;
    const patch::Volume volume = patch::makeVolume(contact, settings);
    const patch::ShapeRange ranges[2] = {patch::shapesOf(bodies, contact, Side::A),
                                         patch::shapesOf(bodies, contact, Side::B)};
    for (int s = 0; s < 2; ++s) {
      const patch::ShapeRange& range = ranges[s];
      for (int k = range.first; k < range.last; ++k) {
        const Shape& shape = range.body->shapes[static_cast<size_t>(k)];
        const size_t first = chunk.vertices.size();
        patch::collectTriangles(volume, shape, patch::shapePose(*range.body, k),
                                s == 0 ? Side::A : Side::B, meshes, chunk.scratch, chunk.vertices);
        if (chunk.vertices.size() == first) continue;
        const int tile = static_cast<int>(2 * c) + s;
        const TileVertex tv{
            {static_cast<float>((tile % per_row) * r), static_cast<float>((tile / per_row) * r)},
            s == 0 ? -1.0f : 1.0f,
            static_cast<float>(volume.half_depth)};
        chunk.tiles.resize(chunk.vertices.size(), tv);
        chunk.draws.push_back({&shape.surface, 0, 0, 0, static_cast<GLint>(first),
                               static_cast<GLsizei>(chunk.vertices.size() - first)});
      }
    }
    out[i] = {&contact,
              patch::gainsOf(ranges[0], ranges[1], settings.mu0),
              out[i].model,
              {patch::firstSurface(ranges[0]), patch::firstSurface(ranges[1])},
              {ranges[0].first, ranges[1].first}};
  }
}

void GlPatchSampler::Impl::upload(GLuint buffer, size_t vertex_size,
                                  const std::function<const void*(const Chunk&)>& data) const {
  // One allocation for the pass, each chunk's vertices at its base.
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertex_count * vertex_size), nullptr,
               GL_STREAM_DRAW);
  for (size_t k = 0; k < chunk_count; ++k) {
    const Chunk& chunk = chunks[k];
    if (chunk.vertices.empty()) continue;
    glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(chunk.base * vertex_size),
                    static_cast<GLsizeiptr>(chunk.vertices.size() * vertex_size), data(chunk));
  }
}

void GlPatchSampler::Impl::batchByMaterial() {
  // Stable: a tile's draws keep their order, which decides exact depth ties.
  order.resize(draws.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return std::tuple(draws[a].map, draws[a].mask, draws[a].heights) <
           std::tuple(draws[b].map, draws[b].mask, draws[b].heights);
  });
  batches.clear();
  firsts.clear();
  counts.clear();
  for (size_t i : order) {
    const Draw& d = draws[i];
    if (batches.empty() || batches.back().map != d.map || batches.back().mask != d.mask ||
        batches.back().heights != d.heights)
      batches.push_back({d.map, d.mask, d.heights, firsts.size(), 0});
    firsts.push_back(d.first);
    counts.push_back(d.count);
    ++batches.back().count;
  }
}

void GlPatchSampler::Impl::setPatchUniforms(const gl::Program& program,
                                            const FrictionSettings& settings) const {
  program.set("u_half_width", static_cast<float>(0.5 * settings.patch_width));
  program.set("u_pixel", static_cast<float>(settings.patch_width / settings.patch_resolution));
  program.set("u_tile_pixels", static_cast<float>(settings.patch_resolution));
  program.set("u_atlas_pixels", static_cast<float>(atlas.size()));
  program.set("u_mu_max", settings.mu_max);
  program.set("u_texel_nudge",
              settings.texel_reading == TexelReading::Nearest ? patch::kNearestTexelNudge : 0.0f);
  program.set("u_scale", atlas.floatTargets() ? 1.0f : 1.0f / settings.mu_max);
  program.set("u_normal_map", 0);
  program.set("u_mask", 1);
  program.set("u_heights", 2);
}

void GlPatchSampler::Impl::drawBatches(const gl::Program& program) {
  for (const Batch& batch : batches) {
    program.set("u_has_map", batch.map != 0 ? 1 : 0);
    program.set("u_has_mask", batch.mask != 0 ? 1 : 0);
    program.set("u_has_heights", batch.heights != 0 ? 1 : 0);
    const GLuint units[3] = {batch.map, batch.mask, batch.heights};
    for (GLenum u = 0; u < 3; ++u) {
      glActiveTexture(GL_TEXTURE0 + u);
      glBindTexture(GL_TEXTURE_2D, units[u]);
    }
    glMultiDrawArrays(GL_TRIANGLES, firsts.data() + batch.first, counts.data() + batch.first,
                      static_cast<GLsizei>(batch.count));
  }
  glActiveTexture(GL_TEXTURE0);
}

void GlPatchSampler::Impl::beginDraw() {
  // Upload this pass's triangles and their tiles.
  glBindVertexArray(*vao);
  upload(*vbo, sizeof(patch::PatchVertex), [](const Chunk& c) { return c.vertices.data(); });
  upload(*tile_vbo, sizeof(TileVertex), [](const Chunk& c) { return c.tiles.data(); });
  batchByMaterial();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // back faces are already discarded (patch_triangles)
  glDisable(GL_BLEND);
  for (int i = 0; i < glpatch::kTileClipPlanes; ++i) glEnable(GL_CLIP_DISTANCE0 + i);
}

void GlPatchSampler::Impl::endDraw(const char* what) {
  for (int i = 0; i < glpatch::kTileClipPlanes; ++i) glDisable(GL_CLIP_DISTANCE0 + i);
  glBindVertexArray(0);
  gl::checkGlError(what);
}

void GlPatchSampler::Impl::render(const FrictionSettings& settings) {
  beginDraw();
  const std::vector<Vec2> dirs = sampleDirections(settings.directions);
  // Each sub-pass renders every batch with its share of the direction groups.
  for (int s = 0; s < atlas.subPasses(); ++s) {
    const int first_group = s * atlas.groupsPerPass();
    const int groups = std::min(atlas.groupsPerPass(), atlas.groups() - first_group);
    const gl::Program& program = programs.get(groups);
    program.use();
    std::array<GLfloat, 2 * 4 * glpatch::kMaxGroupsPerPass> d{};
    for (int k = 0; k < 4 * groups; ++k) {
      d[static_cast<size_t>(2 * k)] =
          static_cast<float>(dirs[static_cast<size_t>(4 * first_group + k)].x());
      d[static_cast<size_t>(2 * k + 1)] =
          static_cast<float>(dirs[static_cast<size_t>(4 * first_group + k)].y());
    }
    glUniform2fv(program.location("u_directions"), 4 * groups, d.data());
    setPatchUniforms(program, settings);
    atlas.beginSubPass(s);  // the whole atlas is the viewport
    drawBatches(program);
  }
  endDraw("gl sampler render");
}

void GlPatchSampler::Impl::sampleFragments(
    std::span<const Body> bodies, std::span<Contact* const> contacts,
    std::span<const models::FrictionModelVariant* const> contact_models,
    const FrictionSettings& settings, double dt) {
  const int r = settings.patch_resolution, per_row = atlas.size() / r;
  const size_t per_pass = static_cast<size_t>(per_row * per_row / 2);
  for (const Contact* c : contacts) heights.prepare(bodies, *c);
  fragment_atlas.ensure(atlas.size());
  const std::vector<Vec2> dirs = sampleDirections(settings.directions);
  std::vector<PassContact>& pass = pass_contacts[0];
  for (size_t first = 0; first < contacts.size(); first += per_pass) {
    const size_t count = std::min(per_pass, contacts.size() - first);
    pass.resize(count);
    for (size_t k = 0; k < count; ++k) pass[k].model = contact_models[first + k];
    collect(bodies, contacts.subspan(first, count), settings, pass, true);
    beginDraw();
    const gl::Program& program = programs.get(0);
    program.use();
    setPatchUniforms(program, settings);
    fragment_atlas.begin();
    drawBatches(program);
    endDraw("gl sampler fragment render");
    const int tiles = static_cast<int>(2 * count);
    fragment_atlas.read(std::min(atlas.size(), ((tiles - 1) / per_row + 1) * r), fragment_pixels);
    ++passes;
    const Clock::time_point t0 = Clock::now();
    for (size_t k = 0; k < count; ++k) {
      const models::ModelInputs in{dirs, pass[k].gains,    settings.mu_max,
                                   dt,   pass[k].surfaces, pass[k].shapes};
      reduction.reduce(fragment_pixels, atlas.size(), r, static_cast<int>(2 * k), *pass[k].model,
                       in, settings.patch_width, *pass[k].contact);
    }
    averaging_ms += msSince(t0);
  }
}

void GlPatchSampler::Impl::average(int slot, const FrictionSettings& settings) {
  glpatch::Readback& rb = readbacks[static_cast<size_t>(slot)];
  rb.map();
  const Clock::time_point t0 = Clock::now();
  const auto n = static_cast<size_t>(settings.directions);
  const size_t stride = glpatch::SumLayout{.directions = settings.directions}.stride();
  // Each contact: the GPU's Eq. 8 sums over its tiles' common coverage, then Eq. 7. The mapped
  // sums are plain memory: the pool's threads read them, each contact writing only its own
  // coefficients; unmap waits for them, on this thread.
  const std::vector<PassContact>& contacts = pass_contacts[static_cast<size_t>(slot)];
  forEachOn(pool, contacts.size(), 64, [&](size_t c) {
    std::array<double, kMaxDirections> sums_a{}, sums_b{};
    double count = 0.0;
    for (size_t lane = 0; lane < glpatch::kSumLanes; ++lane) {
      const float* sums = rb.sums() + (c * glpatch::kSumLanes + lane) * stride;
      count += sums[0];
      for (size_t k = 0; k < n; ++k) {
        sums_a[k] += sums[1 + k];
        sums_b[k] += sums[1 + n + k];
      }
    }
    models::ModelInputs in;
    in.gains = contacts[c].gains;
    in.mu_max = settings.mu_max;
    contacts[c].model->finish_sums(std::span<const double>(sums_a.data(), n),
                                   std::span<const double>(sums_b.data(), n),
                                   static_cast<int>(count), in, *contacts[c].contact);
  });
  rb.unmap();
  averaging_ms += msSince(t0);
}

GlPatchSampler::GlPatchSampler(const GlSamplerOptions& options) : impl_(std::make_unique<Impl>()) {
  if (options.atlas_size < 16 || options.atlas_size > 16384) {
    throw Error("gl sampler: atlas_size must be in [16, 16384], got " +
                std::to_string(options.atlas_size));
  }
  impl_->options = options;
  if (!options.use_current_context) impl_->context = std::make_unique<gl::GlContext>();
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &impl_->max_draw_buffers);
  impl_->setupVertexArray();
}

GlPatchSampler::~GlPatchSampler() {
  if (impl_->context) impl_->context->makeCurrent();
}

void GlPatchSampler::setThreadPool(const ThreadPool* pool) {
  impl_->pool = pool;
}

ProviderStats GlPatchSampler::lastStats() const {
  ProviderStats stats = stats_;
  stats.patch_ms = impl_->patch_ms;
  stats.averaging_ms = impl_->averaging_ms;
  stats.passes = impl_->passes;
  return stats;
}

std::string GlPatchSampler::renderer() const {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return text != nullptr ? text : "";
}

void GlPatchSampler::Impl::abandon() {
  if (!call.active) return;
  for (glpatch::Readback& rb : readbacks) {
    if (!rb.pending()) continue;
    rb.map();
    rb.unmap();
  }
  call.saved.restore();
  call.active = false;
}

void GlPatchSampler::computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                                         const FrictionSettings& settings) {
  startCoefficients(bodies, contacts, settings);
  finishCoefficients();
}

void GlPatchSampler::startCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                                       const FrictionSettings& settings) {
  validate(settings, "gl sampler");
  if (settings.directions % 4 != 0) {
    throw Error("gl sampler: directions must be a multiple of 4 (one RGBA target per 4), got " +
                std::to_string(settings.directions));
  }
  Impl& im = *impl_;
  if (im.context && !im.context->isCurrent()) im.context->makeCurrent();
  im.abandon();
  const int r = settings.patch_resolution;
  if (r > im.options.atlas_size) {
    throw Error("gl sampler: patch_resolution " + std::to_string(r) + " exceeds the atlas (" +
                std::to_string(im.options.atlas_size) + ")");
  }
  const Clock::time_point start = Clock::now();
  im.call.saved = glpatch::SavedState::capture();
  im.call.active = true;
  im.call.bodies = bodies;
  im.call.contacts = contacts;
  im.call.settings = settings;
  im.averaging_ms = 0.0;
  im.passes = 0;
  im.atlas.ensure(im.options.atlas_size, im.options.float_targets, settings.directions / 4,
                  im.max_draw_buffers);
  const int per_row = im.atlas.size() / r;
  const size_t per_pass = static_cast<size_t>(per_row * per_row / 2);
  // Contacts whose earlier sample still holds keep it; the others are rendered: summed on the
  // device where their model needs only P's sums, else read back whole and reduced here.
  im.splitByModel(
      keepSamples(bodies, contacts, settings), [&](const Contact& c) -> const auto& {
        return modelOf(bodies, c);
      });
  if (!im.whole.empty())
    im.sampleFragments(bodies, im.whole, im.whole_models, settings, models().dt);
  const std::span<Contact* const> sampled(im.summed);
  // Passes of at most per_pass contacts; pass p's read-back overlaps pass p + 1's rendering.
  for (size_t first = 0; first < sampled.size(); first += per_pass) {
    const int slot = im.passes % 2;
    if (im.readbacks[static_cast<size_t>(slot)].pending()) im.average(slot, settings);
    const size_t count = std::min(per_pass, sampled.size() - first);
    std::vector<PassContact>& pass = im.pass_contacts[static_cast<size_t>(slot)];
    pass.resize(count);
    for (size_t k = 0; k < count; ++k) pass[k].model = &modelOf(bodies, *sampled[first + k]);
    im.collect(bodies, sampled.subspan(first, count), settings, pass);
    im.render(settings);
    const glpatch::SumLayout layout{static_cast<int>(count), r, settings.directions,
                                    im.atlas.floatTargets() ? 1.0f : settings.mu_max};
    im.readbacks[static_cast<size_t>(slot)].start(im.atlas, im.programs, layout);
    ++im.passes;
  }
  // The device starts on what is queued while the caller works.
  glFlush();
  im.call.busy_ms = msSince(start);
}

void GlPatchSampler::finishCoefficients() {
  Impl& im = *impl_;
  if (!im.call.active) return;
  const Clock::time_point start = Clock::now();
  if (im.context && !im.context->isCurrent()) im.context->makeCurrent();
  // Drain the passes still in flight.
  for (int k = 0; k < 2; ++k) {
    const int slot = (im.passes + k) % 2;
    if (im.readbacks[static_cast<size_t>(slot)].pending()) im.average(slot, im.call.settings);
  }
  im.call.saved.restore();
  im.call.active = false;
  rememberSamples(im.call.bodies, im.call.contacts);
  im.patch_ms = im.call.busy_ms + msSince(start) - im.averaging_ms;
}

}  // namespace asperity
