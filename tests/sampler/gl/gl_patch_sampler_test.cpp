// The OpenGL sampler on this machine's OpenGL (Mesa llvmpipe headless in CI): the shared sampler
// suite with RGBA8 and float targets, and agreement with the CPU reference sampler. No context
// means failing tests, not skipped ones.
#include "asperity/sampler/gl_patch_sampler.hpp"

#include <epoxy/gl.h>

#include <cstdio>

#include "asperity/contact_area/mechanical.hpp"
#include "asperity/gl/context.hpp"
#include "asperity/sampler/cpu_patch_sampler.hpp"
#include "asperity/scene/gl_sampler_provider.hpp"
#include "asperity/scene/scene.hpp"
#include "parallel/thread_pool.hpp"
#include "sampler/sampler_suite.hpp"
#include "support/test_support.hpp"

namespace asperity::sampler_test {
namespace {

// RGBA8 packing: one quantisation step of mu_max / 255 per coefficient.
struct GlTraits {
  static std::unique_ptr<FrictionProvider> make() { return std::make_unique<GlPatchSampler>(); }
  static double tolerance() { return kDefaultMuMax / 255.0; }
  static double tessellationTolerance() { return kDefaultMuMax / 255.0; }
  static bool multipleOf4Only() { return true; }
  static double curvedCoverageTolerance() { return 0.25; }
};

struct GlFloatTraits {
  static std::unique_ptr<FrictionProvider> make() {
    GlSamplerOptions o;
    o.float_targets = true;
    return std::make_unique<GlPatchSampler>(o);
  }
  static double tolerance() { return 1e-4; }
  // A GPU's texture unit weighs bilinear taps in steps (1/256 of a texel on NVIDIA's), so the
  // same surface drawn as other triangles, whose interpolated uvs differ in their last bits,
  // can take the next step: on an H200, 2e-4 apart over this suite's 0.3-ish coefficients.
  static double tessellationTolerance() { return 1e-3; }
  static bool multipleOf4Only() { return true; }
  static double curvedCoverageTolerance() { return 0.25; }
};

INSTANTIATE_TYPED_TEST_SUITE_P(Gl, SamplerSuite, GlTraits);
INSTANTIATE_TYPED_TEST_SUITE_P(GlFloat, SamplerSuite, GlFloatTraits);

// Many textured box-corner contacts at assorted poses and frames: the GL sampler (several passes
// of a small atlas, and 32 directions over two sub-passes) gives the CPU sampler's numbers.
std::vector<Contact> corners(Scene& scene, int count) {
  std::vector<Contact> contacts;
  for (int i = 0; i < count; ++i) {
    const double angle = 0.37 * i;
    Contact c =
        contactAt(Vec3(0.1 - 0.002 * (i % 5), 0.1 - 0.003 * (i % 3), 0.0), 1e-4 * (i % 4), angle);
    contacts.push_back(c);
  }
  (void)scene;
  return contacts;
}

void expectAgreement(GlSamplerOptions options, int n, double tolerance) {
  Scene scene{{planeBody(roughMap(32, 1), 0.05, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, roughMap(32, 2), 0.08, 2.0)},
              {}};
  std::vector<Contact> cpu = corners(scene, 40), gl = cpu;
  CpuPatchSampler reference;
  GlPatchSampler sampler(options);
  const FrictionSettings s = settings(n);
  reference.computeCoefficients(scene.bodies, cpu, s);
  sampler.computeCoefficients(scene.bodies, gl, s);
  for (size_t i = 0; i < cpu.size(); ++i) {
    EXPECT_NEAR(gl[i].covered_pixels, cpu[i].covered_pixels, 2) << "contact " << i;
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(gl[i].mu.mu[k], cpu[i].mu.mu[k], tolerance) << "contact " << i << " k " << k;
    }
  }
  if (options.atlas_size == 64) {
    EXPECT_EQ(sampler.lastStats().passes, 5);  // 8 contacts per pass
  }
}

TEST(GlPatchSampler, AgreesWithCpuOverSeveralPasses) {
  GlSamplerOptions o;
  o.atlas_size = 64;
  expectAgreement(o, 4, 3.0 * 4.0 / 255.0);
}

TEST(GlPatchSampler, FloatTargetsAgreeWithCpuForManyDirections) {
  GlSamplerOptions o;
  o.float_targets = true;
  expectAgreement(o, 32, 3e-3);
}

// With the caller's context the sampler gives the same numbers and leaves its GL state alone.
TEST(GlPatchSampler, UsesAndRestoresTheCallersContext) {
  gl::GlContext context;
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(1, 2, 3, 4);
  GlSamplerOptions o;
  o.use_current_context = true;
  GlPatchSampler sampler(o);
  Scene scene{{planeBody(roughMap(8, 1), 0.1, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, roughMap(8, 2), 0.1, 1.0)},
              contactAt(Vec3(0.1, 0.1, 0.0), 1e-4)};
  std::vector<Contact> gl{scene.contact}, cpu{scene.contact};
  sampler.computeCoefficients(scene.bodies, gl, settings());
  CpuPatchSampler().computeCoefficients(scene.bodies, cpu, settings());
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(gl[0].mu.mu[k], cpu[0].mu.mu[k], 4.0 / 255.0);
  GLint bound = 0, viewport[4] = {};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(static_cast<GLuint>(bound), fbo);
  EXPECT_EQ(viewport[2], 3);
  EXPECT_TRUE(context.isCurrent());
  glDeleteFramebuffers(1, &fbo);
}

TEST(GlPatchSampler, ReusesTheSamplesOfContactsThatBarelyMoved) {
  // Forty corner contacts sampled, then again after moving half of them by 0.05 pixel and the
  // other half by 2 pixels along t, with reuse_pixels 0.1: the first half keeps its samples
  // (close to fresh ones: over 0.05 pixel a few pixel centres cross a texel edge of these very
  // rough maps, slopes up to 1, and read the neighbouring facet), the second half is rendered
  // again (the CPU reference's numbers to RGBA8 rounding).
  Scene scene{{planeBody(roughMap(32, 1), 0.05, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, roughMap(32, 2), 0.08, 2.0)},
              {}};
  FrictionSettings s = settings(4);
  s.reuse_pixels = 0.1;
  std::vector<Contact> contacts = corners(scene, 40);
  for (size_t i = 0; i < contacts.size(); ++i) contacts[i].key = i + 1;  // matched by key
  GlPatchSampler sampler;
  sampler.computeCoefficients(scene.bodies, contacts, s);
  EXPECT_EQ(sampler.lastStats().reused, 0);
  // The contact points slide over both surfaces.
  const double pixel = s.patch_width / s.patch_resolution;
  std::vector<Contact> moved = contacts;
  for (size_t i = 0; i < moved.size(); ++i)
    moved[i].point += (i % 2 == 0 ? 0.05 : 2.0) * pixel * moved[i].t;
  std::vector<Contact> fresh = moved;
  sampler.computeCoefficients(scene.bodies, moved, s);
  FrictionSettings every = s;
  every.reuse_pixels = 0.0;
  CpuPatchSampler().computeCoefficients(scene.bodies, fresh, every);
  EXPECT_EQ(sampler.lastStats().reused, 20);
  for (size_t i = 0; i < moved.size(); ++i)
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(moved[i].mu.mu[k], fresh[i].mu.mu[k], i % 2 == 0 ? 0.06 : kDefaultMuMax / 255.0)
          << "contact " << i << " k " << k;
  // Forgetting the history samples everything again.
  sampler.forgetHistory();
  sampler.computeCoefficients(scene.bodies, moved, s);
  EXPECT_EQ(sampler.lastStats().reused, 0);
}

TEST(GlPatchSampler, StartedCallFinishesWithTheNumbersOfOneCall) {
  // start queues the rendering and returns; finish waits and averages. Between them the
  // sampler's own GL state is bound; after finish the caller's is back. The numbers are those
  // of computeCoefficients, bit for bit. A call started again before it finished is dropped.
  gl::GlContext context;
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  GlSamplerOptions o;
  o.use_current_context = true;
  o.atlas_size = 64;  // several passes: the earlier ones are averaged inside start
  GlPatchSampler sampler(o);
  EXPECT_TRUE(sampler.runsAsynchronously());
  Scene scene{{planeBody(roughMap(32, 1), 0.05, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, roughMap(32, 2), 0.08, 2.0)},
              {}};
  const FrictionSettings s = settings(4);
  std::vector<Contact> whole = corners(scene, 40), split = whole, dropped = whole;
  sampler.computeCoefficients(scene.bodies, whole, s);
  sampler.startCoefficients(scene.bodies, dropped, s);
  sampler.startCoefficients(scene.bodies, split, s);
  sampler.finishCoefficients();
  sampler.finishCoefficients();  // nothing in flight: does nothing
  for (size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(split[i].covered_pixels, whole[i].covered_pixels) << "contact " << i;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(split[i].mu.mu[k], whole[i].mu.mu[k]) << "contact " << i;
  }
  GLint bound = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  EXPECT_EQ(static_cast<GLuint>(bound), fbo);
  glDeleteFramebuffers(1, &fbo);
}

TEST(GlPatchSampler, CollectsAndAveragesOnThePoolWithTheBitsOfOneThread) {
  // Several passes, each collected in runs of contacts and averaged on four threads: the same
  // coefficients, bit for bit, as on the calling thread alone.
  Scene scene{{planeBody(roughMap(32, 1), 0.05, 1.0),
               boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, roughMap(32, 2), 0.08, 2.0)},
              {}};
  GlSamplerOptions o;
  o.atlas_size = 256;  // 128 contacts a pass: four runs of 32
  GlPatchSampler alone(o), pooled(o);
  const ThreadPool pool(4);
  pooled.setThreadPool(&pool);
  const FrictionSettings s = settings(8);
  std::vector<Contact> one = corners(scene, 300), four = one;
  alone.computeCoefficients(scene.bodies, one, s);
  pooled.computeCoefficients(scene.bodies, four, s);
  EXPECT_EQ(pooled.lastStats().passes, 3);
  for (size_t i = 0; i < one.size(); ++i) {
    EXPECT_GT(four[i].covered_pixels, 0) << "contact " << i;
    EXPECT_EQ(four[i].covered_pixels, one[i].covered_pixels) << "contact " << i;
    EXPECT_EQ(four[i].fallback, one[i].fallback) << "contact " << i;
    for (int k = 0; k < 8; ++k) EXPECT_EQ(four[i].mu.mu[k], one[i].mu.mu[k]) << "contact " << i;
  }
}

// The gl sampler handed each step whole, so the world does not overlap it with the solver.
class WholeCalls : public FrictionProvider {
 public:
  std::string name() const override { return "gl-whole"; }
  void computeCoefficients(std::span<const Body> bodies, std::span<Contact> contacts,
                           const FrictionSettings& settings) override {
    gl_.computeCoefficients(bodies, contacts, settings);
  }

 private:
  GlPatchSampler gl_;
};

TEST(GlPatchSampler, WorldSetsUpTheSolverWhileItRendersWithTheSameBits) {
  // The world sets up the solver's contact rows between start and finish: the state is the
  // same, bit for bit, as with the sampler's work done in one call.
  SceneDesc scene = loadScene(test::sourcePath("scenes/stacking.json"));
  InstantiateOptions options;
  addGlPatchSampler(options.providers);
  options.providers.add("gl-whole", [] { return std::make_unique<WholeCalls>(); });
  scene.friction_provider = "gl";
  const std::unique_ptr<World> overlapped = instantiate(scene, options);
  scene.friction_provider = "gl-whole";
  const std::unique_ptr<World> whole = instantiate(scene, options);
  size_t contacts = 0;
  for (int i = 0; i < 40; ++i) {
    overlapped->step();
    whole->step();
    contacts += overlapped->contacts().size();
    ASSERT_EQ(overlapped->stateHash(), whole->stateHash()) << "step " << i;
  }
  EXPECT_GT(contacts, 0u);
}

TEST(GlPatchSampler, WorldStateIsTheSameOnOneAndFourThreads) {
  // With the gl sampler too, the state hash does not depend on the thread count (SPEC 9): the
  // pool collects the triangles (boxes; meshes, hulls and curved shapes through the shared
  // mesh cache) and finishes the sums, the calling thread keeps every GL call.
  for (const char* name : {"stacking.json", "examples/shapes.json", "examples/meshes.json"}) {
    SceneDesc scene = loadScene(test::sourcePath(std::string("scenes/") + name));
    scene.friction_provider = "gl";
    InstantiateOptions options;
    addGlPatchSampler(options.providers);
    const std::unique_ptr<World> one = instantiate(scene, options);
    const std::unique_ptr<World> four = instantiate(scene, options);
    four->settings().threads = 4;
    size_t contacts = 0;
    for (int i = 0; i < 30; ++i) {
      one->step();
      four->step();
      contacts += one->contacts().size();
      ASSERT_EQ(four->stateHash(), one->stateHash()) << name << ", step " << i;
    }
    EXPECT_GT(contacts, 0u) << name;
  }
}

TEST(GlPatchSampler, ReportsRendererAndRejectsBadAtlas) {
  GlPatchSampler sampler;
  EXPECT_FALSE(sampler.renderer().empty());
  GlSamplerOptions o;
  o.atlas_size = 8;
  EXPECT_THROW(GlPatchSampler bad(o), Error);
}

// The contact-area model reads each pixel's fragment, not P's sums: the GL sampler reads its
// fragments back and gives the CPU sampler's coefficients. A rough acrylic plane (plaster, its
// heights from the generator) under a flat steel box, at two loads, several contact points and
// frame angles, and two textures.
TEST(GlPatchSampler, ContactAreaModelGivesTheCpuSamplersNumbers) {
  FrictionModelSettings area;
  area.model = FrictionModel::ContactArea;
  area.dt = 0.01;
  CpuPatchSampler cpu;
  GlPatchSampler gl;
  cpu.setFrictionModels(area);
  gl.setFrictionModels(area);
  const FrictionSettings s = settings(8, 32, 0.02);
  double worst = 0.0;
  for (const uint64_t seed : {3u, 4u}) {
    GeneratorSpec plaster;
    plaster.name = "plaster";
    plaster.size = 64;
    plaster.seed = seed;
    Body plane = planeBody(std::make_shared<NormalMap>(generateNormalMap(plaster)), 0.04, 1.5);
    plane.shapes[0].surface.source.generator = plaster;
    plane.shapes[0].surface.mechanical = findMechanical("acrylic");
    Body box = boxBody(Vec3(0.1, 0.1, 0.1), {Vec3(0, 0, 0.1)}, nullptr, 0.1, 1.0);
    box.shapes[0].surface.mechanical = findMechanical("steel");
    const std::vector<Body> bodies{plane, box};
    std::vector<Contact> contacts;
    for (int i = 0; i < 6; ++i) {
      Contact c = contactAt(Vec3(0.003 * i, -0.002 * i, 0.0), 1e-5, 0.4 * i);
      c.lambda_n = (i % 2 == 0 ? 50.0 : 500.0) * area.dt;
      contacts.push_back(c);
    }
    std::vector<Contact> on_gl = contacts, paper = contacts;
    cpu.computeCoefficients(bodies, contacts, s);
    gl.computeCoefficients(bodies, on_gl, s);
    GlPatchSampler().computeCoefficients(bodies, paper, s);
    for (size_t i = 0; i < contacts.size(); ++i) {
      // The model ran: a part of P is in contact, and adhesion replaced mu0.
      EXPECT_GT(contacts[i].covered_pixels, 0);
      EXPECT_LT(contacts[i].covered_pixels, paper[i].covered_pixels);
      EXPECT_EQ(on_gl[i].covered_pixels, contacts[i].covered_pixels) << "contact " << i;
      for (size_t k = 0; k < 8; ++k) {
        const double apart = std::abs(double(on_gl[i].mu.mu[k]) - double(contacts[i].mu.mu[k]));
        worst = std::max(worst, apart / double(contacts[i].mu.mu[k]));
      }
    }
  }
  EXPECT_LT(worst, 0.01) << "largest relative difference of any direction";
  std::printf("contact-area model, GL against CPU: largest relative difference %.2g\n", worst);
  EXPECT_EQ(gl.lastStats().sampled, 6);
}

// A provider without patches serves the paper's model only, and says so.
TEST(GlPatchSampler, ProvidersWithoutPatchesRefuseTheContactAreaModel) {
  FrictionModelSettings area;
  area.setPair("steel", "oak", FrictionModel::ContactArea);
  FrictionProviders providers = FrictionProviders::builtIn();
  for (const char* name : {"constant", "cone"}) {
    try {
      providers.make(name)->setFrictionModels(area);
      FAIL() << name;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("friction model contact_area reads the fragments of "
                                           "each patch: it needs a patch sampler"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW(providers.make("cpu")->setFrictionModels(area));
}

}  // namespace
}  // namespace asperity::sampler_test
