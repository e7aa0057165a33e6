// Turns a World into a RenderScene: every body's shapes as shape meshes (built once by
// buildShapeMesh, the same uv and tangent frames the patch samplers use), their surfaces'
// normal maps and base colours, planes as a finite ground with the grid, and the debug layers
// of the last step. Also the default camera of a world and ray picking for the viewer.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <utility>

#include "asperity/render/camera.hpp"
#include "asperity/render/render_scene.hpp"
#include "asperity/world/debug_draw.hpp"
#include "asperity/world/world.hpp"

namespace asperity::render {

struct WorldViewOptions {
  DebugDrawOptions debug;      // layers of the last step's contacts (layers = 0: none)
  int segments = 48;           // around curved shapes
  BodyId highlight = kNoBody;  // body drawn with a rim tint (the viewer's dragged body)
};

struct PickHit {
  BodyId body = kNoBody;
  Vec3 point = Vec3::Zero();  // world point hit (m)
  double distance = 0.0;      // along the ray (m)
};

class WorldView {
 public:
  // Fills `scene` from the world's current state (meshes are cached between calls).
  void update(const World& world, const WorldViewOptions& options, RenderScene& scene);
  // The camera framing the world's non-plane bodies at this aspect ratio.
  Camera defaultCamera(const World& world, double aspect);
  // The nearest body hit by a ray (unit direction), optionally only dynamic ones.
  std::optional<PickHit> pick(const World& world, const Vec3& origin, const Vec3& direction,
                              bool dynamic_only = true);

 private:
  std::shared_ptr<const ShapeMesh> meshFor(const World& world, BodyId body, int shape,
                                           const WorldViewOptions& options);
  Eigen::AlignedBox3d focus(const World& world, const WorldViewOptions& options);

  std::map<std::pair<BodyId, int>, std::shared_ptr<const ShapeMesh>> meshes_;
  Vec3 ground_centre_ = Vec3::Zero();
  double ground_size_ = 0.0;
};

// One-shot version of WorldView::update (no mesh cache).
RenderScene renderWorld(const World& world, const WorldViewOptions& options = {});

}  // namespace asperity::render
