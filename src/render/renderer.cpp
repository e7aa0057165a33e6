// The frame: shadow map from the light, background, shaded meshes, debug layers, MSAA resolve.
#include "asperity/render/renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

#include "asperity/error.hpp"
#include "asperity/gl/shader.hpp"
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

// Orthographic projection of a box [-r, r]^2 x [near, far] (OpenGL clip depth).
Mat4f ortho(double r, double n, double f) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = 1.0 / r;
  m(1, 1) = 1.0 / r;
  m(2, 2) = -2.0 / (f - n);
  m(2, 3) = -(f + n) / (f - n);
  return m.cast<float>();
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
  gl::Program mesh{
      "renderer/mesh",
      {{GL_VERTEX_SHADER, shaders::kMeshVertex}, {GL_FRAGMENT_SHADER, shaders::kMeshFragment}}};
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

  void makeTargets(const RendererOptions& o);
  void makeShadowMap(int size);
  Mat4f lightViewProj(const Eigen::AlignedBox3d& focus, const Vec3& light) const;
  void drawShadows(const RenderScene& scene, const Mat4f& light_vp);
  void drawMeshes(const RenderScene& scene, const Camera& camera, const RendererOptions& o,
                  const Mat4f& light_vp);
};

void Renderer::Impl::makeTargets(const RendererOptions& o) {
  // MSAA colour + depth renderbuffers.
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples = std::clamp(o.samples, 1, std::max(1, max_samples));
  width = o.width;
  height = o.height;
  msaa_fbo = std::make_unique<gl::Framebuffer>();
  msaa_color = std::make_unique<gl::Renderbuffer>();
  msaa_depth = std::make_unique<gl::Renderbuffer>();
  // One sample means plain storage: drivers may round a multisample count of 1 up to 4.
  for (auto [buffer, format] :
       {std::pair{msaa_color.get(), GL_RGBA8}, std::pair{msaa_depth.get(), GL_DEPTH_COMPONENT24}}) {
    glBindRenderbuffer(GL_RENDERBUFFER, *buffer);
    if (samples > 1) {
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
      glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, *msaa_fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, *msaa_color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, *msaa_depth);
  gl::checkFramebufferComplete("renderer MSAA target");
  // Single-sample colour texture the MSAA frame resolves into.
  resolve_fbo = std::make_unique<gl::Framebuffer>();
  resolve_color = std::make_unique<gl::Texture>();
  glBindTexture(GL_TEXTURE_2D, *resolve_color);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, *resolve_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *resolve_color, 0);
  gl::checkFramebufferComplete("renderer resolve target");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::Impl::makeShadowMap(int size) {
  shadow_size = size;
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

Mat4f Renderer::Impl::lightViewProj(const Eigen::AlignedBox3d& focus, const Vec3& light) const {
  // A directional light: an orthographic box around the focus' bounding sphere.
  const Vec3 centre = focus.center();
  const double r = std::max(0.6 * focus.diagonal().norm(), 0.05);
  Camera view;
  view.target = centre;
  view.eye = centre + light.normalized() * (2.0 * r);
  if (std::abs(light.normalized().z()) > 0.99) view.up = Vec3::UnitY();
  return ortho(r, 0.5 * r, 3.5 * r) * view.view();
}

void Renderer::Impl::drawShadows(const RenderScene& scene, const Mat4f& light_vp) {
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

void Renderer::Impl::drawMeshes(const RenderScene& scene, const Camera& camera,
                                const RendererOptions& o, const Mat4f& light_vp) {
  const Mat4f view_proj = camera.projection(double(width) / height) * camera.view();
  const Eigen::AlignedBox3d focus = focusBounds(scene);
  const double distance = (camera.eye - camera.target).norm();
  const double fog_start = 1.5 * distance + 2.0 * 0.5 * focus.diagonal().norm();
  // Per-frame uniforms.
  mesh.use();
  mesh.set("u_view_proj", view_proj);
  mesh.set("u_light_view_proj", light_vp);
  mesh.set("u_light_dir", Vec3f(o.light_direction.normalized().cast<float>()));
  mesh.set("u_eye", Vec3f(camera.eye.cast<float>()));
  mesh.set("u_horizon", kSkyBottom);
  mesh.set("u_fog_start", static_cast<float>(fog_start));
  mesh.set("u_fog_end", static_cast<float>(3.0 * fog_start));
  mesh.set("u_grid_step", static_cast<float>(o.grid_step));
  mesh.set("u_shadows", shadow_size > 0 ? 1 : 0);
  mesh.set("u_shadow_texel", shadow_size > 0 ? 1.0f / static_cast<float>(shadow_size) : 0.0f);
  mesh.set("u_normal_map", 0);
  mesh.set("u_shadow_map", 1);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, shadow_depth ? shadow_depth->id() : 0);
  // Per-item material and pose; bodies before the ground so that depth testing rejects the
  // ground's fragments behind them before they are shaded.
  std::vector<const RenderItem*> order;
  for (const RenderItem& item : scene.items)
    if (item.mesh && !item.ground) order.push_back(&item);
  for (const RenderItem& item : scene.items)
    if (item.mesh && item.ground) order.push_back(&item);
  for (const RenderItem* pointer : order) {
    const RenderItem& item = *pointer;
    const GpuMesh& gpu = meshes.get(item.mesh);
    const bool mapped = o.normal_maps && item.normal_map && !item.normal_map->empty();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, mapped ? textures.get(item.normal_map) : 0);
    mesh.set("u_has_normal_map", mapped ? 1 : 0);
    mesh.set("u_model", modelMatrix(item.pose));
    mesh.set("u_base_color", Vec3f(item.base_color.cast<float>()));
    mesh.set("u_ground", item.ground ? 1 : 0);
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
  const Mat4f light_vp = r.lightViewProj(focusBounds(scene), options_.light_direction);
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
  // Resolve MSAA into the single-sample texture.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, *r.msaa_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, *r.resolve_fbo);
  glBlitFramebuffer(0, 0, r.width, r.height, 0, 0, r.width, r.height, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
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
