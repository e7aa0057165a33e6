// Normal-map preview and cone plot.
#include "surface_preview.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "asperity/world/debug_draw.hpp"

namespace asperity::viewer {
namespace {

ImU32 colorOf(const Vec3& c) {
  return IM_COL32(static_cast<int>(255 * c.x()), static_cast<int>(255 * c.y()),
                  static_cast<int>(255 * c.z()), 255);
}

// The polar polygon through mu_k d_k (t to the right, b up), scaled to fit `size`.
void drawCone(const DirectionalMu& mu, double mu0, float size) {
  ImDrawList* list = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 centre(origin.x + 0.5f * size, origin.y + 0.5f * size);
  double largest = mu0;
  for (int k = 0; k < mu.count; ++k)
    largest = std::max(largest, double(mu.mu[static_cast<size_t>(k)]));
  const float scale = largest > 0.0 ? static_cast<float>(0.45 * size / largest) : 0.0f;
  // Axes, and the isotropic circle of mu0 for reference.
  list->AddRectFilled(origin, ImVec2(origin.x + size, origin.y + size), IM_COL32(30, 30, 34, 255));
  list->AddLine(ImVec2(origin.x, centre.y), ImVec2(origin.x + size, centre.y),
                IM_COL32(90, 90, 90, 255));
  list->AddLine(ImVec2(centre.x, origin.y), ImVec2(centre.x, origin.y + size),
                IM_COL32(90, 90, 90, 255));
  if (mu0 > 0.0)
    list->AddCircle(centre, static_cast<float>(mu0) * scale, IM_COL32(150, 150, 150, 255), 64);
  // Edges coloured by direction, as the renderer's cone layer.
  std::vector<ImVec2> points;
  for (int k = 0; k < mu.count; ++k) {
    const double angle = 2.0 * kPi * k / mu.count;
    const float r = mu.mu[static_cast<size_t>(k)] * scale;
    points.emplace_back(centre.x + r * static_cast<float>(std::cos(angle)),
                        centre.y - r * static_cast<float>(std::sin(angle)));
  }
  for (int k = 0; k < mu.count; ++k) {
    const ImU32 c = colorOf(directionColor(2.0 * kPi * k / mu.count));
    list->AddLine(centre, points[static_cast<size_t>(k)], c, 1.0f);
    list->AddLine(points[static_cast<size_t>(k)], points[static_cast<size_t>((k + 1) % mu.count)],
                  c, 2.0f);
  }
  ImGui::Dummy(ImVec2(size, size));
}

}  // namespace

void SurfacePreview::upload(const NormalMap& map) {
  // rgb = 0.5 n + 0.5, rows as stored (bottom-up; the image call flips v).
  std::vector<uint8_t> rgb;
  rgb.reserve(map.texels().size() * 3);
  for (const Vec3f& n : map.texels())
    for (int c = 0; c < 3; ++c)
      rgb.push_back(static_cast<uint8_t>(std::clamp(127.5f * (n[c] + 1.0f), 0.0f, 255.0f)));
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, map.width(), map.height(), 0, GL_RGB, GL_UNSIGNED_BYTE,
               rgb.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void SurfacePreview::draw(const std::shared_ptr<const NormalMap>& map, double gain, double mu0,
                          int directions) {
  if (!map || map->empty()) {
    ImGui::TextUnformatted("flat surface (no normal map): mu = mu0 in every direction");
    return;
  }
  // Re-upload and recompute only when the map or the gains change.
  const bool new_map = shown_.lock() != map;
  if (new_map) {
    upload(*map);
    shown_ = map;
  }
  if (new_map || gain != cone_gain_ || mu0 != cone_mu0_ || directions != cone_directions_) {
    PatchConeOptions opt;
    opt.directions = std::clamp(directions, kMinDirections, kMaxDirections);
    opt.gains = PatchGains{mu0, 0.0, gain};
    cone_ = flatPatchCone(nullptr, *map, opt);
    cone_gain_ = gain;
    cone_mu0_ = mu0;
    cone_directions_ = directions;
  }
  const float size = 180.0f;
  ImGui::Text("%d x %d texels", map->width(), map->height());
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture_.id())),
               ImVec2(size, size), ImVec2(0, 1), ImVec2(1, 0));
  ImGui::SameLine();
  drawCone(cone_, mu0, size);
  ImGui::Text("cone vs flat: mu(+t) %.3f  mu(+b) %.3f  mu(-t) %.3f  mu(-b) %.3f", cone_.along(0.0),
              cone_.along(0.5 * kPi), cone_.along(kPi), cone_.along(1.5 * kPi));
}

}  // namespace asperity::viewer
