// One surface of one contact patch (SPEC 3, Sec. 4.1): vertices are already in the contact
// frame (x along t, y along b, z along n, origin at the contact point); the orthographic view
// maps the w x w footprint onto the vertex's tile of the atlas and the depth clip
// |z| <= half_depth onto the near and far planes. Depth grows away from the other body, so
// GL_LESS keeps the fragment nearest to it (largest z for B, smallest for A). The tile, side and
// depth clip come with each vertex, so that one draw covers the triangles of many contacts.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec3 a_tangent;
layout(location = 3) in vec3 a_bitangent;
layout(location = 4) in vec3 a_normal;
layout(location = 5) in vec4 a_edge0;  // the triangle's exact edge tests (patch_triangles.hpp)
layout(location = 6) in vec4 a_edge1;
layout(location = 7) in vec4 a_edge2;
// The tile's lower-left corner (atlas pixels), the side (+1 surface B, -1 surface A) and the
// contact's half depth.
layout(location = 8) in vec4 a_tile;

uniform float u_half_width;
uniform float u_tile_pixels;   // a tile's width and height
uniform float u_atlas_pixels;  // the atlas's width and height

out vec2 v_uv;
out vec3 v_tangent;
out vec3 v_bitangent;
out vec3 v_normal;
flat out vec4 v_edge0;
flat out vec4 v_edge1;
flat out vec4 v_edge2;
flat out vec2 v_tile_origin;
flat out float v_side;
out float v_depth;  // the CPU raster's depth key: z for B, -z for A

void main() {
  vec2 footprint = a_position.xy / u_half_width;  // -1 .. 1 across the tile
  vec2 window = a_tile.xy + 0.5 * (footprint + 1.0) * u_tile_pixels;
  gl_Position = vec4(window * (2.0 / u_atlas_pixels) - 1.0, -a_tile.z * a_position.z / a_tile.w, 1.0);
  // The footprint's sides clip each triangle to its own tile, as a viewport per tile would.
  gl_ClipDistance[0] = 1.0 - footprint.x;
  gl_ClipDistance[1] = 1.0 + footprint.x;
  gl_ClipDistance[2] = 1.0 - footprint.y;
  gl_ClipDistance[3] = 1.0 + footprint.y;
  v_tile_origin = a_tile.xy;
  v_side = a_tile.z;
  v_depth = a_tile.z * a_position.z;
  v_uv = a_uv;
  v_tangent = a_tangent;
  v_bitangent = a_bitangent;
  v_normal = a_normal;
  v_edge0 = a_edge0;
  v_edge1 = a_edge1;
  v_edge2 = a_edge2;
}
