// What the renderer draws, independent of World: shape meshes placed in the world, each with
// its surface's normal map (the very one friction reads) and base colour, plus the debug draw
// list. renderWorld (render/world_view.hpp) fills one from a World; tests build their own.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "asperity/geometry/shape_mesh.hpp"
#include "asperity/math/types.hpp"
#include "asperity/texture/color_image.hpp"
#include "asperity/texture/normal_map.hpp"
#include "asperity/world/debug_draw.hpp"

namespace asperity::render {

struct RenderItem {
  // Triangles in the shape frame with uv (texture repeats) and (T, B, N) per vertex.
  std::shared_ptr<const ShapeMesh> mesh;
  Transform pose;  // shape frame -> world
  // The surface's tangent-space normal map (rows bottom-up, x along T, y along B); null = flat.
  std::shared_ptr<const NormalMap> normal_map;
  Vec3 base_color = Vec3(0.7, 0.7, 0.7);  // linear RGB albedo
  // An sRGB colour texture (rows bottom-up) multiplying base_color along the mesh's uvs; null =
  // none.
  std::shared_ptr<const ColorImage> base_color_texture;
  bool ground = false;     // draw the grid on it; casts no shadow
  bool highlight = false;  // selected in the viewer (rim tint)
  uint32_t id = 0;         // caller's tag (body id), handed back by picking
};

struct RenderScene {
  std::vector<RenderItem> items;
  DebugDrawList debug;
  // Bounds of what the camera should frame (non-ground items); empty = use all items.
  Eigen::AlignedBox3d focus;
  // Half the size of everything drawn (ground included), for shadow and clip planes (m).
  double scene_radius = 0.0;
};

// World-space bounds of an item's mesh.
Eigen::AlignedBox3d itemBounds(const RenderItem& item);

}  // namespace asperity::render
