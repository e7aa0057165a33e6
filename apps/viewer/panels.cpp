// ImGui panels: simulation controls, live settings, bodies and surfaces, step profile.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "asperity/error.hpp"
#include "viewer.hpp"

namespace asperity::viewer {
namespace {

// A combo box over an enumeration's name table (the names scenes use).
template <typename Enum>
void enumCombo(const char* label, Enum& value, EnumNames<Enum> names) {
  if (!ImGui::BeginCombo(label, nameOf(value, names))) return;
  for (const auto& [name, e] : names)
    if (ImGui::Selectable(name, e == value)) value = e;
  ImGui::EndCombo();
}

bool inputDouble(const char* label, double& value, double lo, double hi, const char* format) {
  double v = value;
  if (!ImGui::DragScalar(label, ImGuiDataType_Double, &v, static_cast<float>((hi - lo) * 0.002),
                         &lo, &hi, format))
    return false;
  value = std::clamp(v, lo, hi);
  return true;
}

}  // namespace

void Viewer::drawPanels() {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(390, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("Asperity");
  simulationPanel();
  if (ImGui::CollapsingHeader("Friction and solver", ImGuiTreeNodeFlags_DefaultOpen))
    settingsPanel();
  if (ImGui::CollapsingHeader("Bodies and surfaces")) bodiesPanel();
  if (ImGui::CollapsingHeader("Step profile", ImGuiTreeNodeFlags_DefaultOpen)) profilePanel();
  ImGui::End();
}

void Viewer::simulationPanel() {
  // Play, pause, step, reset, time scale.
  if (ImGui::Button(playing_ ? "Pause" : "Play")) playing_ = !playing_;
  ImGui::SameLine();
  if (ImGui::Button("Step")) step_once_ = true;
  ImGui::SameLine();
  if (ImGui::Button("Reset")) reset();
  ImGui::SameLine();
  ImGui::Text("t = %.3f s", world_->time());
  float scale = static_cast<float>(time_scale_);
  if (ImGui::SliderFloat("time scale", &scale, 0.01f, 4.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
    time_scale_ = scale;
  // Another scene by path.
  char path[512] = {};
  std::strncpy(path, open_path_.c_str(), sizeof path - 1);
  if (ImGui::InputText("##scene", path, sizeof path)) open_path_ = path;
  ImGui::SameLine();
  if (ImGui::Button("Open")) loadScene(open_path_);
  // Debug layers.
  static constexpr std::array<std::pair<const char*, uint32_t>, 4> layers = {
      {{"contacts", kLayerContacts},
       {"frames", kLayerFrames},
       {"cones", kLayerCones},
       {"patches", kLayerPatches}}};
  for (size_t i = 0; i < layers.size(); ++i) {
    bool on = (view_options_.debug.layers & layers[i].second) != 0;
    if (i > 0) ImGui::SameLine();
    if (ImGui::Checkbox(layers[i].first, &on)) view_options_.debug.layers ^= layers[i].second;
  }
  float spring = static_cast<float>(spring_stiffness_);
  if (ImGui::SliderFloat("mouse spring (N/m/kg)", &spring, 1.0f, 1000.0f, "%.0f",
                         ImGuiSliderFlags_Logarithmic))
    spring_stiffness_ = spring;
  if (!message_.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", message_.c_str());
}

void Viewer::settingsPanel() {
  WorldSettings& s = world_->settings();
  FrictionSettings& f = s.friction;
  // Eq. 7 and the patch (SPEC 3).
  inputDouble("mu0", f.mu0, 0.0, 2.0, "%.3f");
  inputDouble("w (m)", f.patch_width, 0.001, 0.2, "%.4f");
  ImGui::SliderInt("R (pixels)", &f.patch_resolution, 2, 64);
  ImGui::SliderInt("N (directions)", &f.directions, kMinDirections, 32);
  ImGui::SliderFloat("mu_max", &f.mu_max, 0.5f, 8.0f, "%.2f");
  // Limit surface and frame (SPEC 4, 5).
  enumCombo("limit surface", s.limit_surface, kLimitSurfaceNames);
  enumCombo("frame mode", s.frame.mode, kFrameModeNames);
  ImGui::SliderInt("iterations", &s.iterations, 1, 200);
  // The friction provider.
  const std::string current = world_->frictionProvider().name();
  if (ImGui::BeginCombo("sampler", current.c_str())) {
    for (const std::string& name : providers_.names()) {
      if (ImGui::Selectable(name.c_str(), name == current) && name != current) {
        try {
          world_->setFrictionProvider(providers_.make(name));
        } catch (const Error& e) {
          message_ = e.what();
        }
      }
    }
    ImGui::EndCombo();
  }
}

void Viewer::bodiesPanel() {
  const auto bodies = world_->bodies();
  // One node per body; per shape its gain k, colour, and the texture with its cone.
  for (BodyId id = 0; id < bodies.size(); ++id) {
    Body& body = world_->body(id);
    ImGui::PushID(static_cast<int>(id));
    if (ImGui::TreeNode("body", "%s%s", body.name.empty() ? "(unnamed)" : body.name.c_str(),
                        body.isDynamic() ? "" : " (static)")) {
      for (size_t i = 0; i < body.shapes.size(); ++i) {
        Surface& surface = body.shapes[i].surface;
        ImGui::PushID(static_cast<int>(i));
        ImGui::Text("shape %zu", i);
        inputDouble("k (gain)", surface.gain, 0.0, 20.0, "%.2f");
        float color[3] = {static_cast<float>(surface.base_color.x()),
                          static_cast<float>(surface.base_color.y()),
                          static_cast<float>(surface.base_color.z())};
        if (ImGui::ColorEdit3("colour", color))
          surface.base_color = Vec3(color[0], color[1], color[2]);
        if (ImGui::TreeNode("texture and cone")) {
          preview_->draw(surface.normal_map, surface.gain, world_->settings().friction.mu0,
                         std::max(world_->settings().friction.directions, 16));
          ImGui::TreePop();
        }
        ImGui::PopID();
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

void Viewer::profilePanel() {
  const StepProfile& p = world_->profile();
  ImGui::Text("%.1f fps   render %.1f ms   step %.2f ms", fps_, render_ms_, step_ms_);
  ImGui::Text("contacts %d   fallbacks %d", p.contacts, p.fallbacks);
  // Per-stage times of the last step (ms), in step order, the provider's share under friction
  // and the solve's parts under solve.
  for (int i = 0; i < kStageCount; ++i) {
    const auto stage = static_cast<Stage>(i);
    ImGui::Text("%-16s %8.3f ms", stageName(stage), p.ms(stage));
    if (stage == Stage::Friction) {
      ImGui::Text("%-16s %8.3f ms", "  patch", p.patch_ms);
      ImGui::Text("%-16s %8.3f ms", "  averaging", p.averaging_ms);
    }
    if (stage == Stage::Solve) {
      for (int k = 0; k < kSolveStageCount; ++k) {
        const auto part = static_cast<SolveStage>(k);
        ImGui::Text("  %-14s %8.3f ms", solveStageName(part), p.solve_ms[static_cast<size_t>(k)]);
      }
    }
  }
  ImGui::Text("%-16s %8.3f ms", "total", p.total_ms);
}

}  // namespace asperity::viewer
