// The frame: shadow map from the light, background, shaded meshes, debug layers, MSAA resolve.
#include "asperity/render/renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "asperity/error.hpp"
#include "gl/shader.hpp"
#include "render/debug_pass.hpp"
#include "render/gpu_cache.hpp"
#include "render/shaders.hpp"

namespace asperity::render {
namespace {

const Vec3f kSkyTop(0.64f, 0.73f, 0.86f);
const Vec3f kSkyBottom(0.93f, 0.94f, 0.96f);

Mat4f modelMatrix(const Transform& pose) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = pose.rotation.normalized().toRotationMatrix();
  m.block<3, 1>(0, 3) = pose.position;
  return m.cast<float>();
}

// Orthographic projection of the view-space box [l, r] x [b, t] x [-f, -n] (OpenGL clip depth).
Eigen::Matrix4d ortho(double l, double r, double b, double t, double n, double f) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = 2.0 / (r - l);
  m(0, 3) = -(r + l) / (r - l);
  m(1, 1) = 2.0 / (t - b);
  m(1, 3) = -(t + b) / (t - b);
  m(2, 2) = -2.0 / (f - n);
  m(2, 3) = -(f + n) / (f - n);
  return m;
}

// Bounds of the shadow casters (every item but the ground).
Eigen::AlignedBox3d casterBounds(const RenderScene& scene) {
  Eigen::AlignedBox3d box;
  for (const RenderItem& item : scene.items)
    if (!item.ground) box.extend(itemBounds(item));
  return box;
}

// The mesh shader variant for one surface: normal map, ground grid, shadows, PCF taps, base
// colour texture.
std::string meshFragmentSource(int variant) {
  const auto define = [](const char* name, int value) {
    return "#define " + std::string(name) + " " + std::to_string(value) + "\n";
  };
  return "#version 430 core\n" + define("NORMAL_MAP", variant & 1) +
         define("GROUND", (variant >> 1) & 1) + define("SHADOWS", (variant >> 2) & 1) +
         define("SHADOW_TAPS", (variant & 8) != 0 ? 4 : 1) +
         define("BASE_COLOR_MAP", (variant >> 4) & 1) + shaders::kMeshFragmentBody;
}

// What the camera and the light look at: the focus bounds, else every item's.
Eigen::AlignedBox3d focusBounds(const RenderScene& scene) {
  if (!scene.focus.isEmpty()) return scene.focus;
  Eigen::AlignedBox3d box;
  for (const RenderItem& item : scene.items)
    if (!item.ground) box.extend(itemBounds(item));
  if (box.isEmpty()) box = Eigen::AlignedBox3d(Vec3::Constant(-0.5), Vec3::Constant(0.5));
  return box;
}

}  // namespace

Eigen::AlignedBox3d itemBounds(const RenderItem& item) {
  Eigen::AlignedBox3d box;
  if (!item.mesh) return box;
  for (const Vec3f& p : item.mesh->positions) box.extend(item.pose.apply(p.cast<double>()));
  return box;
}

struct Renderer::Impl {
  // Mesh programs by variant (bit 0 normal map, 1 ground, 2 shadows, 3 four PCF taps, 4 base
  // colour texture), compiled
  // on first use.
  std::array<std::unique_ptr<gl::Program>, 32> mesh_variants;
  gl::Program shadow{
      "renderer/shadow",
      {{GL_VERTEX_SHADER, shaders::kShadowVertex}, {GL_FRAGMENT_SHADER, shaders::kShadowFragment}}};
  gl::Program background{"renderer/background",
                         {{GL_VERTEX_SHADER, shaders::kBackgroundVertex},
                          {GL_FRAGMENT_SHADER, shaders::kBackgroundFragment}}};
  DebugPass debug;
  MeshCache meshes;
  TextureCache textures;
  gl::VertexArray empty_vao;  // core profile needs a VAO even for attribute-less draws

  // MSAA target, single-sample resolve target, shadow map.
  std::unique_ptr<gl::Framebuffer> msaa_fbo, resolve_fbo, shadow_fbo;
  std::unique_ptr<gl::Renderbuffer> msaa_color, msaa_depth;
  std::unique_ptr<gl::Texture> resolve_color, shadow_depth;
  int width = 0, height = 0, samples = 0, shadow_size = 0;
  int frames = 0;
  // What the shadow map holds (light matrix, then each caster's mesh and model matrix): the
  // pass is skipped while nothing that casts has moved.
  std::vector<float> shadow_key;

  const gl::Program& meshProgram(int variant);

  void makeTargets(const RendererOptions& o);
  void makeShadowMap(int size);
  Mat4f lightViewProj(const RenderScene& scene, const Vec3& light) const;
  void drawShadows(const RenderScene& scene, const Mat4f& light_vp);
  void setFrameUniforms(const gl::Program& program, const Camera& camera, const RendererOptions& o,
                        const Mat4f& light_vp, const Mat4f& view_proj, double fog_start) const;
  void drawMeshes(const RenderScene& scene, const Camera& camera, const RendererOptions& o,
                  const Mat4f& light_vp);
};

void Renderer::Impl::makeTargets(const RendererOptions& o) {
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples = std::clamp(o.samples, 1, std::max(1, max_samples));
  width = o.width;
  height = o.height;
  // Single-sample colour texture the frame ends in (read back, blitted to windows).
  resolve_fbo = std::make_unique<gl::Framebuffer>();
  resolve_color = std::make_unique<gl::Texture>();
  glBindTexture(GL_TEXTURE_2D, *resolve_color);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, *resolve_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *resolve_color, 0);
  gl::checkFramebufferComplete("renderer resolve target");
  // The drawing target: MSAA colour + depth renderbuffers; with one sample, plain depth and the
  // resolve texture itself as colour, so no copy is needed (drivers may round a multisample
  // count of 1 up to 4).
  msaa_fbo = std::make_unique<gl::Framebuffer>();
  msaa_color = std::make_unique<gl::Renderbuffer>();
  msaa_depth = std::make_unique<gl::Renderbuffer>();
  for (auto [buffer, format] :
       {std::pair{msaa_color.get(), GL_RGBA8}, std::pair{msaa_depth.get(), GL_DEPTH_COMPONENT24}}) {
    if (samples == 1 && buffer == msaa_color.get()) continue;
    glBindRenderbuffer(GL_RENDERBUFFER, *buffer);
    if (samples > 1) {
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
      glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, *msaa_fbo);
  if (samples > 1) {
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, *msaa_color);
  } else {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *resolve_color, 0);
  }
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, *msaa_depth);
  gl::checkFramebufferComplete("renderer MSAA target");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::Impl::makeShadowMap(int size) {
  shadow_size = size;
  shadow_key.clear();
  shadow_fbo.reset();
  shadow_depth.reset();
  if (size <= 0) return;
  // Depth texture with hardware comparison (sampler2DShadow), lit outside its border.
  shadow_depth = std::make_unique<gl::Texture>();
  glBindTexture(GL_TEXTURE_2D, *shadow_depth);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, size, size);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  shadow_fbo = std::make_unique<gl::Framebuffer>();
  glBindFramebuffer(GL_FRAMEBUFFER, *shadow_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, *shadow_depth, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  gl::checkFramebufferComplete("renderer shadow map");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

const gl::Program& Renderer::Impl::meshProgram(int variant) {
  std::unique_ptr<gl::Program>& program = mesh_variants[static_cast<size_t>(variant)];
  if (!program) {
    const std::string fragment = meshFragmentSource(variant);
    program = std::make_unique<gl::Program>(
        "renderer/mesh", std::vector<gl::ShaderSource>{{GL_VERTEX_SHADER, shaders::kMeshVertex},
                                                       {GL_FRAGMENT_SHADER, fragment}});
  }
  return *program;
}

Mat4f Renderer::Impl::lightViewProj(const RenderScene& scene, const Vec3& light) const {
  // A directional light: an orthographic box fitted to the casters' bounds seen from the light
  // (all the map's texels land where shadows can fall), reaching 3 radii beyond them for the
  // receivers.
  Eigen::AlignedBox3d casters = casterBounds(scene);
  if (casters.isEmpty()) casters = focusBounds(scene);
  const Vec3 centre = casters.center();
  const double r = std::max(0.5 * casters.diagonal().norm(), 0.05);
  Camera view;
  view.target = centre;
  view.eye = centre + light.normalized() * (2.0 * r);
  if (std::abs(light.normalized().z()) > 0.99) view.up = Vec3::UnitY();
  const Eigen::Matrix4d light_view = view.view().cast<double>();
  Eigen::AlignedBox3d box;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p = casters.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
    box.extend((light_view * p.homogeneous()).head<3>());
  }
  // A margin of a few texels keeps the filter footprint inside the map.
  const double margin = 0.02 * std::max(box.sizes().x(), box.sizes().y()) + 1e-3;
  const double near = -box.max().z() - margin, far = -box.min().z() + 3.0 * r;
  return (ortho(box.min().x() - margin, box.max().x() + margin, box.min().y() - margin,
                box.max().y() + margin, near, far) *
          light_view)
      .cast<float>();
}

void Renderer::Impl::drawShadows(const RenderScene& scene, const Mat4f& light_vp) {
  // Skip the pass when the light and every caster's mesh and pose are as last drawn.
  std::vector<float> key(light_vp.data(), light_vp.data() + 16);
  for (const RenderItem& item : scene.items) {
    if (item.ground || !item.mesh) continue;
    const Mat4f model = modelMatrix(item.pose);
    key.push_back(static_cast<float>(reinterpret_cast<uintptr_t>(item.mesh.get()) % 16777213u));
    key.insert(key.end(), model.data(), model.data() + 16);
  }
  if (key == shadow_key) return;
  shadow_key = std::move(key);
  glBindFramebuffer(GL_FRAMEBUFFER, *shadow_fbo);
  glViewport(0, 0, shadow_size, shadow_size);
  glClear(GL_DEPTH_BUFFER_BIT);
  shadow.use();
  shadow.set("u_light_view_proj", light_vp);
  // Closed meshes: back faces into the map reduce acne on lit faces.
  glCullFace(GL_FRONT);
  for (const RenderItem& item : scene.items) {
    if (item.ground || !item.mesh) continue;
    const GpuMesh& gpu = meshes.get(item.mesh);
    shadow.set("u_model", modelMatrix(item.pose));
    glBindVertexArray(gpu.vao);
    glDrawElements(GL_TRIANGLES, gpu.index_count, GL_UNSIGNED_INT, nullptr);
  }
  glCullFace(GL_BACK);
}

void Renderer::Impl::setFrameUniforms(const gl::Program& program, const Camera& camera,
                                      const RendererOptions& o, const Mat4f& light_vp,
                                      const Mat4f& view_proj, double fog_start) const {
  program.use();
  program.set("u_view_proj", view_proj);
  program.set("u_light_view_proj", light_vp);
  program.set("u_light_dir", Vec3f(o.light_direction.normalized().cast<float>()));
  program.set("u_eye", Vec3f(camera.eye.cast<float>()));
  program.set("u_horizon", kSkyBottom);
  program.set("u_fog_start", static_cast<float>(fog_start));
  program.set("u_fog_end", static_cast<float>(3.0 * fog_start));
  program.set("u_grid_step", static_cast<float>(o.grid_step));
  program.set("u_shadow_texel", shadow_size > 0 ? 1.0f / static_cast<float>(shadow_size) : 0.0f);
  program.set("u_normal_map", 0);
  program.set("u_shadow_map", 1);
  program.set("u_base_color_map", 2);
}

void Renderer::Impl::drawMeshes(const RenderScene& scene, const Camera& camera,
                                const RendererOptions& o, const Mat4f& light_vp) {
  const Mat4f view_proj = camera.projection(double(width) / height) * camera.view();
  const Eigen::AlignedBox3d focus = focusBounds(scene);
  const double distance = (camera.eye - camera.target).norm();
  const double fog_start = 1.5 * distance + 2.0 * 0.5 * focus.diagonal().norm();
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, shadow_depth ? shadow_depth->id() : 0);
  const int shadow_bits = shadow_size > 0 ? (o.shadow_taps >= 4 ? 4 | 8 : 4) : 0;
  // Bodies before the ground so that depth testing rejects the ground's fragments behind them
  // before they are shaded; per-frame uniforms once per program used.
  std::vector<const RenderItem*> order;
  for (const RenderItem& item : scene.items)
    if (item.mesh && !item.ground) order.push_back(&item);
  for (const RenderItem& item : scene.items)
    if (item.mesh && item.ground) order.push_back(&item);
  unsigned prepared = 0;  // bit per variant whose frame uniforms are set
  for (const RenderItem* pointer : order) {
    const RenderItem& item = *pointer;
    const GpuMesh& gpu = meshes.get(item.mesh);
    const bool mapped = o.normal_maps && item.normal_map && !item.normal_map->empty();
    const bool coloured = item.base_color_texture && !item.base_color_texture->empty();
    const int variant =
        (mapped ? 1 : 0) | (item.ground ? 2 : 0) | shadow_bits | (coloured ? 16 : 0);
    const gl::Program& mesh = meshProgram(variant);
    if ((prepared & (1u << variant)) == 0) {
      setFrameUniforms(mesh, camera, o, light_vp, view_proj, fog_start);
      prepared |= 1u << variant;
    }
    mesh.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, mapped ? textures.get(item.normal_map) : 0);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, coloured ? textures.get(item.base_color_texture) : 0);
    mesh.set("u_model", modelMatrix(item.pose));
    mesh.set("u_base_color", Vec3f(item.base_color.cast<float>()));
    mesh.set("u_highlight", item.highlight ? 1 : 0);
    // The ground is a single-sided quad seen from above; draw both sides anyway.
    if (item.ground) glDisable(GL_CULL_FACE);
    glBindVertexArray(gpu.vao);
    glDrawElements(GL_TRIANGLES, gpu.index_count, GL_UNSIGNED_INT, nullptr);
    if (item.ground) glEnable(GL_CULL_FACE);
  }
  glActiveTexture(GL_TEXTURE0);
}

Renderer::Renderer(const RendererOptions& options) : impl_(std::make_unique<Impl>()) {
  setOptions(options);
}

Renderer::~Renderer() = default;

void Renderer::setOptions(const RendererOptions& options) {
  if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
    throw Error("renderer: size " + std::to_string(options.width) + "x" +
                std::to_string(options.height) + " is outside 1..16384");
  if (options.samples < 1 || options.samples > 64)
    throw Error("renderer: samples " + std::to_string(options.samples) + " is outside 1..64");
  const bool retarget = !impl_->msaa_fbo || options.width != options_.width ||
                        options.height != options_.height || options.samples != options_.samples;
  const bool reshadow = options.shadow_map_size != impl_->shadow_size || !impl_->msaa_fbo;
  options_ = options;
  if (retarget) impl_->makeTargets(options_);
  if (reshadow) impl_->makeShadowMap(std::clamp(options_.shadow_map_size, 0, 8192));
}

void Renderer::resize(int width, int height) {
  RendererOptions o = options_;
  o.width = width;
  o.height = height;
  setOptions(o);
}

void Renderer::render(const RenderScene& scene, const Camera& camera) {
  Impl& r = *impl_;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_FRAMEBUFFER_SRGB);
  // Shadows from the light.
  const Mat4f light_vp = r.lightViewProj(scene, options_.light_direction);
  if (r.shadow_size > 0) r.drawShadows(scene, light_vp);
  // The lit scene, then the background gradient, into the MSAA target.
  glBindFramebuffer(GL_FRAMEBUFFER, *r.msaa_fbo);
  glViewport(0, 0, r.width, r.height);
  glEnable(GL_MULTISAMPLE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  r.drawMeshes(scene, camera, options_, light_vp);
  // The gradient sits on the far plane: drawn after the meshes, it only shades empty pixels.
  glDepthMask(GL_FALSE);
  r.background.use();
  r.background.set("u_top", kSkyTop);
  r.background.set("u_bottom", kSkyBottom);
  glBindVertexArray(r.empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
  // Debug layers over the shaded frame.
  r.debug.draw(scene.debug, camera.projection(double(r.width) / r.height) * camera.view(),
               options_.debug_on_top);
  // Resolve MSAA into the single-sample texture (one sample drew into it directly).
  if (r.samples > 1) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, *r.msaa_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, *r.resolve_fbo);
    glBlitFramebuffer(0, 0, r.width, r.height, 0, 0, r.width, r.height, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  // Free GPU copies of meshes and maps that are gone, now and then.
  if (++r.frames % 120 == 0) {
    r.meshes.prune();
    r.textures.prune();
  }
}

Image Renderer::readPixels() const {
  const Impl& r = *impl_;
  Image image;
  image.width = r.width;
  image.height = r.height;
  std::vector<uint8_t> rows(static_cast<size_t>(r.width) * r.height * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, *r.resolve_fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, r.width, r.height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // OpenGL rows are bottom-up; images are top-down.
  image.rgb.resize(rows.size());
  const size_t stride = static_cast<size_t>(r.width) * 3;
  for (int y = 0; y < r.height; ++y)
    std::copy_n(&rows[static_cast<size_t>(r.height - 1 - y) * stride], stride,
                &image.rgb[static_cast<size_t>(y) * stride]);
  return image;
}

void Renderer::blitTo(unsigned target, int width, int height) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, *impl_->resolve_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
  glBlitFramebuffer(0, 0, impl_->width, impl_->height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                    GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace asperity::render
