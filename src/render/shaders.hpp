// GLSL sources of the renderer (OpenGL 4.3 core). Shading is Blinn-Phong with a hemisphere
// ambient term, one directional key light with a PCF shadow map, tangent-space normal mapping
// in the physics' frame (texel x along T, y along B, z along N; SPEC 6), and an anti-aliased
// grid shaded into the ground (no separate pass).
#pragma once

namespace asperity::render::shaders {

// Surfaces: world position, (T, B, N) frame, uv in texture repeats, light-space position.
inline constexpr const char* kMeshVertex = R"(#version 430 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_tangent;
layout(location = 3) in vec3 a_bitangent;
layout(location = 4) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform mat4 u_light_view_proj;
out vec3 v_world;
out vec3 v_normal;
out vec3 v_tangent;
out vec3 v_bitangent;
out vec2 v_uv;
out vec4 v_light;
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  mat3 rotation = mat3(u_model);  // rigid: the rotation part maps directions
  v_world = world.xyz;
  v_normal = rotation * a_normal;
  v_tangent = rotation * a_tangent;
  v_bitangent = rotation * a_bitangent;
  v_uv = a_uv;
  v_light = u_light_view_proj * world;
  gl_Position = u_view_proj * world;
}
)";

// The fragment shader's body, without its #version line: the renderer compiles one variant per
// combination of NORMAL_MAP, GROUND, SHADOWS and SHADOW_TAPS (1 or 4) by prepending #defines, so
// that a software rasteriser, which runs both sides of a branch under a mask, never pays for a
// texture fetch or a grid that the surface does not use.
inline constexpr const char* kMeshFragmentBody = R"(
in vec3 v_world;
in vec3 v_normal;
in vec3 v_tangent;
in vec3 v_bitangent;
in vec2 v_uv;
in vec4 v_light;
uniform sampler2D u_normal_map;
uniform sampler2D u_base_color_map;
uniform sampler2DShadow u_shadow_map;
uniform int u_highlight;
uniform float u_shadow_texel;
uniform float u_grid_step;
uniform float u_fog_start;
uniform float u_fog_end;
uniform vec3 u_base_color;
uniform vec3 u_light_dir;
uniform vec3 u_eye;
uniform vec3 u_horizon;
out vec4 o_color;

// Percentage-closer filter with hardware comparison: each bilinear tap is a 2 x 2 comparison.
// SHADOW_TAPS 4: four taps one texel apart (a 3 x 3 footprint); 1: one tap (a 2 x 2 footprint,
// soft over a texel of the map).
float shadowFactor(float ndl) {
#if SHADOWS
  vec3 p = v_light.xyz / v_light.w * 0.5 + 0.5;
  float z = p.z - mix(0.0025, 0.0008, clamp(ndl, 0.0, 1.0));
#if SHADOW_TAPS == 4
  float d = u_shadow_texel;
  float lit = 0.25 * (texture(u_shadow_map, vec3(p.xy + vec2(-d, -d), z)) +
                      texture(u_shadow_map, vec3(p.xy + vec2(d, -d), z)) +
                      texture(u_shadow_map, vec3(p.xy + vec2(-d, d), z)) +
                      texture(u_shadow_map, vec3(p.xy + vec2(d, d), z)));
#else
  float lit = texture(u_shadow_map, vec3(p.xy, z));
#endif
  return p.z >= 1.0 ? 1.0 : lit;  // beyond the light's far plane: lit
#else
  return 1.0;
#endif
}

// Anti-aliased lines every `step` metres on the ground's x, y; both grids share one derivative.
float gridLines(vec2 g, vec2 w) {
  vec2 d = abs(fract(g - 0.5) - 0.5) / max(w, vec2(1e-6));
  float line = 1.0 - min(min(d.x, d.y), 1.0);
  return line * clamp(1.0 - 3.0 * max(w.x, w.y), 0.0, 1.0);  // fade where lines crowd
}

void main() {
  // Geometric frame, then the meso normal from the normal map (SPEC 6).
  vec3 N = normalize(v_normal);
  vec3 n = N;
#if NORMAL_MAP
  vec3 T = normalize(v_tangent);
  vec3 B = normalize(v_bitangent);
  vec3 m = texture(u_normal_map, v_uv).xyz * 2.0 - 1.0;  // stored as 0.5 m + 0.5
  n = normalize(m.x * T + m.y * B + m.z * N);
#endif
  vec3 L = normalize(u_light_dir);
  vec3 V = normalize(u_eye - v_world);
  vec3 H = normalize(L + V);
  float ndl = max(dot(n, L), 0.0);
  float facing = step(0.0, dot(N, L));  // no light through the macro surface
  float s = shadowFactor(dot(N, L)) * facing;

  // Key light (Blinn-Phong) plus a sky/ground hemisphere ambient; the ground's grid darkens
  // its albedo (lines every u_grid_step, darker every 10).
  vec3 albedo = u_base_color;
#if BASE_COLOR_MAP
  albedo *= texture(u_base_color_map, v_uv).rgb;  // sRGB texture: already linear here
#endif
#if GROUND
  vec2 g = v_world.xy / u_grid_step;
  vec2 w = fwidth(g);
  albedo *= 1.0 - 0.35 * gridLines(g, w) - 0.25 * gridLines(0.1 * g, 0.1 * w);
#endif
  vec3 ambient = mix(vec3(0.30, 0.28, 0.26), vec3(0.55, 0.60, 0.70), n.z * 0.5 + 0.5);
  float spec = pow(max(dot(n, H), 0.0), 48.0) * 0.25;
  vec3 color = albedo * (0.45 * ambient + 0.85 * ndl * s * vec3(1.0, 0.97, 0.92)) + spec * s;
  if (u_highlight != 0) {
    color = mix(color, vec3(1.0, 0.6, 0.1), 0.35 * pow(1.0 - max(dot(N, V), 0.0), 2.0) + 0.1);
  }

  // Gamma, then fog towards the horizon colour on far ground.
  color = pow(clamp(color, 0.0, 1.0), vec3(1.0 / 2.2));
#if GROUND
  float fog = smoothstep(u_fog_start, u_fog_end, length(u_eye - v_world));
  color = mix(color, u_horizon, fog);
#endif
  o_color = vec4(color, 1.0);
}
)";

// Depth only, from the light.
inline constexpr const char* kShadowVertex = R"(#version 430 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_light_view_proj;
void main() { gl_Position = u_light_view_proj * u_model * vec4(a_position, 1.0); }
)";

inline constexpr const char* kShadowFragment = R"(#version 430 core
void main() {}
)";

// Vertical gradient behind everything (a full-screen triangle, no vertex buffer).
inline constexpr const char* kBackgroundVertex = R"(#version 430 core
out float v_height;
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
  v_height = p.y * 0.5 + 0.5;
  gl_Position = vec4(p, 1.0, 1.0);
}
)";

inline constexpr const char* kBackgroundFragment = R"(#version 430 core
in float v_height;
uniform vec3 u_top;
uniform vec3 u_bottom;
out vec4 o_color;
void main() { o_color = vec4(mix(u_bottom, u_top, v_height), 1.0); }
)";

// Debug layers: coloured lines, round points, translucent polygons (display colours as given).
inline constexpr const char* kDebugVertex = R"(#version 430 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_color;
layout(location = 2) in float a_size;
uniform mat4 u_view_proj;
out vec4 v_color;
void main() {
  v_color = a_color;
  gl_PointSize = a_size;
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
)";

inline constexpr const char* kDebugFragment = R"(#version 430 core
in vec4 v_color;
uniform int u_points;
out vec4 o_color;
void main() {
  if (u_points != 0) {
    vec2 d = gl_PointCoord * 2.0 - 1.0;
    float r = dot(d, d);
    if (r > 1.0) discard;
    o_color = vec4(r > 0.55 ? vec3(0.05) : v_color.rgb, 1.0);  // dark outline
    return;
  }
  o_color = v_color;
}
)";

}  // namespace asperity::render::shaders
