// Debug layers: one dynamic vertex buffer per frame, three draw calls.
#include "render/debug_pass.hpp"

#include <vector>

#include "render/shaders.hpp"

namespace asperity::render {
namespace {

// position (3), colour (4), point size (1).
struct Vertex {
  float x, y, z, r, g, b, a, size;
};

Vertex vertex(const Vec3& p, const Vec3& c, float alpha, float size = 1.0f) {
  return {static_cast<float>(p.x()),
          static_cast<float>(p.y()),
          static_cast<float>(p.z()),
          static_cast<float>(c.x()),
          static_cast<float>(c.y()),
          static_cast<float>(c.z()),
          alpha,
          size};
}

}  // namespace

DebugPass::DebugPass()
    : program_("renderer/debug", {{GL_VERTEX_SHADER, shaders::kDebugVertex},
                                  {GL_FRAGMENT_SHADER, shaders::kDebugFragment}}) {
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  const GLsizei stride = sizeof(Vertex);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(0));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(7 * sizeof(float)));
  glBindVertexArray(0);
}

void DebugPass::draw(const DebugDrawList& list, const Mat4f& view_proj, bool on_top) {
  if (list.empty()) return;
  // One buffer: fill triangles, then lines (explicit lines and polygon outlines), then points.
  std::vector<Vertex> v;
  for (const DebugPolygon& p : list.polygons)
    for (size_t i = 1; p.filled && i + 1 < p.loop.size(); ++i)
      v.insert(v.end(), {vertex(p.loop[0], p.color, 0.35f), vertex(p.loop[i], p.color, 0.35f),
                         vertex(p.loop[i + 1], p.color, 0.35f)});
  const GLsizei triangles = static_cast<GLsizei>(v.size());
  for (const DebugLine& l : list.lines)
    v.insert(v.end(), {vertex(l.a, l.color, 1.0f), vertex(l.b, l.color, 1.0f)});
  for (const DebugPolygon& p : list.polygons)
    for (size_t i = 0; i < p.loop.size(); ++i)
      v.insert(v.end(), {vertex(p.loop[i], p.color, 1.0f),
                         vertex(p.loop[(i + 1) % p.loop.size()], p.color, 1.0f)});
  const GLsizei lines = static_cast<GLsizei>(v.size()) - triangles;
  for (const DebugPoint& p : list.points) v.push_back(vertex(p.position, p.color, 1.0f, p.size));
  const GLsizei points = static_cast<GLsizei>(v.size()) - triangles - lines;

  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(Vertex)), v.data(),
               GL_STREAM_DRAW);
  program_.use();
  program_.set("u_view_proj", view_proj);
  glBindVertexArray(vao_);
  if (on_top) glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_PROGRAM_POINT_SIZE);
  // Translucent fills, crisp lines, round points on top of all.
  program_.set("u_points", 0);
  if (triangles > 0) glDrawArrays(GL_TRIANGLES, 0, triangles);
  if (lines > 0) glDrawArrays(GL_LINES, triangles, lines);
  program_.set("u_points", 1);
  if (points > 0) glDrawArrays(GL_POINTS, triangles + lines, points);
  // Back to the renderer's defaults.
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glBindVertexArray(0);
}

}  // namespace asperity::render
