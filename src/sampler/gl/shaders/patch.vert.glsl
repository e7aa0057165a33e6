// One surface of one contact patch (SPEC 3, Sec. 4.1): vertices are already in the contact
// frame (x along t, y along b, z along n, origin at the contact point); the orthographic view
// maps the w x w footprint onto the tile (the viewport) and the depth clip |z| <= half_depth
// onto the near and far planes. Depth grows away from the other body, so GL_LESS keeps the
// fragment nearest to it (largest z for B, smallest for A).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec3 a_tangent;
layout(location = 3) in vec3 a_bitangent;
layout(location = 4) in vec3 a_normal;
layout(location = 5) in vec4 a_edge0;  // the triangle's exact edge tests (patch_triangles.hpp)
layout(location = 6) in vec4 a_edge1;
layout(location = 7) in vec4 a_edge2;

uniform float u_half_width;
uniform float u_half_depth;
uniform float u_side;  // +1 surface B, -1 surface A

out vec2 v_uv;
out vec3 v_tangent;
out vec3 v_bitangent;
out vec3 v_normal;
flat out vec4 v_edge0;
flat out vec4 v_edge1;
flat out vec4 v_edge2;

void main() {
  gl_Position = vec4(a_position.xy / u_half_width, -u_side * a_position.z / u_half_depth, 1.0);
  v_uv = a_uv;
  v_tangent = a_tangent;
  v_bitangent = a_bitangent;
  v_normal = a_normal;
  v_edge0 = a_edge0;
  v_edge1 = a_edge1;
  v_edge2 = a_edge2;
}
