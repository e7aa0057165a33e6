// The CPU reference patch sampler (cpu_patch_sampler.hpp): rasterise, shade, average, Eq. 7.
#include "asperity/sampler/cpu_patch_sampler.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <vector>

#include "asperity/friction/directions.hpp"
#include "asperity/friction/fragment_model.hpp"
#include "parallel/thread_pool.hpp"
#include "sampler/models/friction_models.hpp"
#include "sampler/patch_common.hpp"
#include "sampler/patch_geometry.hpp"
#include "sampler/patch_heights.hpp"
#include "sampler/patch_reuse.hpp"
#include "sampler/patch_shade.hpp"

namespace asperity {

namespace {

using Clock = std::chrono::steady_clock;

// Narrows b's window to the rows and row spans where a has coverage (empty when a has none):
// only P counts.
void narrowToCoverage(const patch::SurfaceRaster& a, patch::SurfaceRaster& b) {
  const int rows = static_cast<int>(a.cov_lo.size());
  b.wj0 = rows, b.wj1 = -1;
  for (int j = 0; j < rows; ++j) {
    const auto row = static_cast<size_t>(j);
    b.win_lo[row] = std::max(b.win_lo[row], a.cov_lo[row]);
    b.win_hi[row] = std::min(b.win_hi[row], a.cov_hi[row]);
    if (b.win_lo[row] > b.win_hi[row]) continue;
    b.wj0 = std::min(b.wj0, j), b.wj1 = std::max(b.wj1, j);
  }
}

double msBetween(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace

// Scratch kept between calls: rasters, fragment arrays, sample directions.
struct CpuPatchSampler::State {
  State(patch::MeshCache& shared, const CpuSamplerOptions& opt,
        const patch::HeightCache& height_cache)
      : meshes(shared), simd(opt.simd), heights(height_cache) {
    for (size_t m = 0; m < std::size(models::kFrictionModelVariants); ++m)
      if (models::kFrictionModelVariants[m]->make_scratch)
        model_scratch[m] = models::kFrictionModelVariants[m]->make_scratch();
  }
  patch::MeshCache& meshes;           // the sampler's, shared by every thread's state
  SimdCopy simd;                      // the sampler's option, for every loop this state runs
  const patch::HeightCache& heights;  // the sampler's, shared (read only while sampling)
  patch::GeometryScratch geometry;
  std::array<patch::SurfaceRaster, 2> raster;  // A, B
  std::vector<uint32_t> in_patch;              // P as Volume::pack(i, j)
  std::vector<float> gx, gy;                   // P's ploughing vectors, A's then B's
  std::vector<float> height, depth;            // for models that read them, A's then B's
  std::vector<Vec2> directions;
  // Each model's scratch, in FrictionModel's order (null for a model that needs none).
  std::array<std::unique_ptr<models::ModelScratch>, std::size(models::kFrictionModelVariants)>
      model_scratch;
  double patch_ms = 0.0, averaging_ms = 0.0;

  void prepare(const FrictionSettings& settings);
  void rasterise(const patch::Volume& volume, const patch::ShapeRange (&ranges)[2], bool whole);
  // Returns the margins of the depth clip decisions on A and B (patch_reuse.hpp).
  std::array<patch::DepthMargins, 2> sample(std::span<const Body> bodies, Contact& contact,
                                            const FrictionSettings& settings,
                                            const models::FrictionModelVariant& model, double dt,
                                            PatchImages* images);
  void fillImages(const patch::Volume& volume, const FrictionSettings& settings,
                  PatchImages& images);
  // The heights and depths of P's fragments (for a model that reads them).
  void readHeights(const patch::Volume& volume);
  void reserveLike(const State& other);
};

void CpuPatchSampler::State::reserveLike(const State& other) {
  // Every buffer at least as large as other's, and other's directions when this state has
  // none yet: a thread that has not yet sampled such a patch then allocates nothing when it
  // first does.
  if (directions.empty()) directions = other.directions;
  geometry.triangles.reserve(other.geometry.triangles.capacity());
  in_patch.reserve(other.in_patch.capacity());
  gx.reserve(other.gx.capacity());
  gy.reserve(other.gy.capacity());
  height.reserve(other.height.capacity());
  depth.reserve(other.depth.capacity());
  for (size_t m = 0; m < model_scratch.size(); ++m)
    if (model_scratch[m]) model_scratch[m]->reserveLike(*other.model_scratch[m]);
  for (size_t s = 0; s < 2; ++s) {
    patch::SurfaceRaster& r = raster[s];
    const patch::SurfaceRaster& o = other.raster[s];
    r.key.reserve(o.key.capacity());
    r.primitive.reserve(o.primitive.capacity());
    r.planars.reserve(o.planars.capacity());
    r.curveds.reserve(o.curveds.capacity());
    r.win_lo.reserve(o.win_lo.capacity());
    r.win_hi.reserve(o.win_hi.capacity());
    r.cov_lo.reserve(o.cov_lo.capacity());
    r.cov_hi.reserve(o.cov_hi.capacity());
  }
}

void CpuPatchSampler::State::prepare(const FrictionSettings& settings) {
  // Directions for this N; buffers sized for R x R (no allocation once warm).
  if (static_cast<int>(directions.size()) != settings.directions) {
    directions = sampleDirections(settings.directions);
  }
  const auto pixels = static_cast<size_t>(settings.patch_resolution * settings.patch_resolution);
  if (gx.size() < 2 * pixels) {
    gx.resize(2 * pixels);
    gy.resize(2 * pixels);
    in_patch.reserve(pixels);
  }
}

void CpuPatchSampler::State::rasterise(const patch::Volume& volume,
                                       const patch::ShapeRange (&ranges)[2], bool whole) {
  // A first; unless both whole images are wanted, B only where A has fragments (A's coverage
  // spans per row), since only P counts.
  for (int s = 0; s < 2; ++s) {
    patch::SurfaceRaster& r = raster[static_cast<size_t>(s)];
    r.reset(s == 0 ? Side::A : Side::B, volume.resolution);
    if (s == 1 && !whole) narrowToCoverage(raster[0], r);
    const patch::ShapeRange& range = ranges[s];
    for (int k = range.first; k < range.last && r.wj0 <= r.wj1; ++k) {
      patch::rasteriseShape(volume, range.body->shapes[static_cast<size_t>(k)],
                            patch::shapePose(*range.body, k), meshes, geometry, r);
    }
  }
  // P: pixels of the window covered by both, appended branch-free.
  const patch::SurfaceRaster& b = raster[1];
  in_patch.resize(static_cast<size_t>(volume.resolution * volume.resolution));
  size_t count = 0;
  const float* key_a = raster[0].key.data();
  const float* key_b = b.key.data();
  for (int j = b.wj0; j <= b.wj1; ++j) {
    const int lo = b.win_lo[static_cast<size_t>(j)], hi = b.win_hi[static_cast<size_t>(j)];
    for (int i = lo; i <= hi; ++i) {
      const int p = j * volume.resolution + i;
      in_patch[count] = patch::Volume::pack(i, j);
      count += static_cast<size_t>(key_a[p] > patch::SurfaceRaster::kEmpty) &
               static_cast<size_t>(key_b[p] > patch::SurfaceRaster::kEmpty);
    }
  }
  in_patch.resize(count);
}

void CpuPatchSampler::State::fillImages(const patch::Volume& volume,
                                        const FrictionSettings& settings, PatchImages& images) {
  // Every covered pixel of each surface: its meso normal and Eq. 5 per direction.
  const int pixels = volume.resolution * volume.resolution;
  const auto n = static_cast<size_t>(settings.directions);
  images.resolution = volume.resolution;
  images.directions = settings.directions;
  images.in_patch.assign(static_cast<size_t>(pixels), 0);
  for (uint32_t p : in_patch) {
    images.in_patch[(p >> 16) * static_cast<uint32_t>(volume.resolution) + (p & 0xffffu)] = 1;
  }
  for (size_t s = 0; s < 2; ++s) {
    images.covered[s].assign(static_cast<size_t>(pixels), 0);
    images.normals[s].assign(static_cast<size_t>(pixels), Vec3f::Zero());
    images.mu[s].assign(static_cast<size_t>(pixels) * n, 0.0f);
    for (int p = 0; p < pixels; ++p) {
      if (!raster[s].covered(p)) continue;
      const patch::Fragment f = patch::shadeFragment(volume, raster[s], p);
      const Vec2f g = f.gain * ploughingVector(f.m, raster[s].side, settings.mu_max);
      images.covered[s][static_cast<size_t>(p)] = 1;
      images.normals[s][static_cast<size_t>(p)] = f.m.normalized();
      for (size_t k = 0; k < n; ++k) {
        const float mu = g.dot(directions[k].cast<float>());
        images.mu[s][static_cast<size_t>(p) * n + k] = mu > 0.0f ? mu : 0.0f;
      }
    }
  }
}

std::array<patch::DepthMargins, 2> CpuPatchSampler::State::sample(
    std::span<const Body> bodies, Contact& contact, const FrictionSettings& settings,
    const models::FrictionModelVariant& model, double dt, PatchImages* images) {
  const Clock::time_point t0 = Clock::now();
  prepare(settings);
  patch::Volume volume = patch::makeVolume(contact, settings);
  volume.simd = simd;
  const patch::ShapeRange ranges[2] = {patch::shapesOf(bodies, contact, Side::A),
                                       patch::shapesOf(bodies, contact, Side::B)};
  // Rasterise both surfaces and find P, then shade P into ploughing vectors (A, then B).
  rasterise(volume, ranges, images != nullptr);
  const size_t count = in_patch.size();
  for (size_t s = 0; s < 2 && count > 0; ++s) {
    patch::shadePloughing(volume, raster[s], in_patch, settings.mu_max, gx.data() + s * count,
                          gy.data() + s * count);
  }
  if (model.reads_heights) readHeights(volume);
  const Clock::time_point t1 = Clock::now();
  // The contact's model reduces P's fragments.
  models::PatchFragments fragments{volume.resolution, volume.pixel, in_patch};
  models::ModelInputs in{directions, patch::gainsOf(ranges[0], ranges[1], settings.mu0),
                         settings.mu_max, dt};
  for (size_t s = 0; s < 2; ++s) {
    fragments.gx[s] = gx.data() + s * count;
    fragments.gy[s] = gy.data() + s * count;
    if (model.reads_heights) {
      fragments.height[s] = height.data() + s * count;
      fragments.depth[s] = depth.data() + s * count;
    }
    in.surfaces[s] = patch::firstSurface(ranges[s]);
    in.shapes[s] = ranges[s].first;
  }
  in.simd = simd;
  model.reduce(fragments, in, contact, model_scratch[static_cast<size_t>(model.kind)].get());
  const Clock::time_point t2 = Clock::now();
  if (images != nullptr) fillImages(volume, settings, *images);
  patch_ms += msBetween(t0, t1);
  averaging_ms += msBetween(t1, t2);
  return {raster[0].depth, raster[1].depth};
}

void CpuPatchSampler::State::readHeights(const patch::Volume& volume) {
  const size_t count = in_patch.size();
  height.resize(2 * count);
  depth.resize(2 * count);
  for (size_t s = 0; s < 2; ++s) {
    patch::heightsOf(volume, raster[s], in_patch, heights, height.data() + s * count);
    float* out = depth.data() + s * count;
    for (size_t k = 0; k < count; ++k) {
      const uint32_t p = in_patch[k];
      out[k] = raster[s].key[(p >> 16) * static_cast<uint32_t>(volume.resolution) + (p & 0xffffu)];
    }
  }
}

CpuPatchSampler::CpuPatchSampler(const CpuSamplerOptions& options)
    : options_(options),
      meshes_(std::make_unique<patch::MeshCache>()),
      heights_(std::make_unique<patch::HeightCache>()) {
  state_ = std::make_unique<State>(*meshes_, options_, *heights_);
}

CpuPatchSampler::~CpuPatchSampler() = default;

void CpuPatchSampler::prepareHeights(std::span<const Body> bodies,
                                     std::span<Contact* const> contacts) {
  // Made here, on the calling thread, for all threads.
  for (const Contact* c : contacts)
    if (modelOf(bodies, *c).reads_heights) heights_->prepare(bodies, *c);
}

void CpuPatchSampler::sampleContact(std::span<const Body> bodies, Contact& contact,
                                    const FrictionSettings& settings, PatchImages* images) {
  validate(settings, "cpu sampler");
  const models::FrictionModelVariant& model = modelOf(bodies, contact);
  if (model.reads_heights) heights_->prepare(bodies, contact);
  state_->sample(bodies, contact, settings, model, models().dt, images);
}

void CpuPatchSampler::computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                                          const FrictionSettings& settings) {
  validate(settings, "cpu sampler");
  // Contacts whose earlier sample still holds keep it; the others are sampled.
  const std::span<Contact* const> to_sample = keepSamples(bodies, contacts, settings);
  prepareHeights(bodies, to_sample);
  if (!pool_ || pool_->concurrency() == 1) {
    // One contact after the other; scratch is reused.
    State& st = *state_;
    st.patch_ms = st.averaging_ms = 0.0;
    for (Contact* c : to_sample)
      reuse().margins(static_cast<size_t>(c - contacts.data())) =
          st.sample(bodies, *c, settings, modelOf(bodies, *c), models().dt, nullptr);
    stats_.patch_ms = st.patch_ms;
    stats_.averaging_ms = st.averaging_ms;
  } else {
    sampleOnPool(bodies, contacts, to_sample, settings);
  }
  rememberSamples(bodies, contacts);
}

void CpuPatchSampler::sampleOnPool(std::span<const Body> bodies, std::span<Contact> contacts,
                                   std::span<Contact* const> to_sample,
                                   const FrictionSettings& settings) {
  // Every mesh the contacts may rasterise is built here, on the calling thread: the threads
  // then only look the cache up, and share one BVH per mesh.
  for (const Contact* c : to_sample) patch::prepareMeshes(*meshes_, bodies, *c, false);
  while (worker_states_.size() < static_cast<size_t>(pool_->concurrency()))
    worker_states_.push_back(std::make_unique<State>(*meshes_, options_, *heights_));
  for (auto& st : worker_states_) st->patch_ms = st->averaging_ms = 0.0;
  // Each contact is sampled alone (it writes only itself), with the scratch of the thread
  // that runs it: the coefficients are the same whichever thread that is.
  pool_->forEach(to_sample.size(), 4, [&](size_t k) {
    Contact& c = *to_sample[k];
    State& st = *worker_states_[static_cast<size_t>(pool_->slot())];
    reuse().margins(static_cast<size_t>(&c - contacts.data())) =
        st.sample(bodies, c, settings, modelOf(bodies, c), models().dt, nullptr);
  });
  stats_.patch_ms = stats_.averaging_ms = 0.0;
  for (const auto& st : worker_states_) {
    stats_.patch_ms += st->patch_ms;
    stats_.averaging_ms += st->averaging_ms;
  }
  // Which thread samples which contact varies from step to step: every thread's scratch
  // grows to the largest, so that a warmed-up step allocates on no thread.
  for (auto& st : worker_states_) {
    for (const auto& other : worker_states_) st->reserveLike(*other);
  }
}

}  // namespace asperity
