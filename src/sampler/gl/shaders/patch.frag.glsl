// Eq. 5 per fragment for GROUPS x 4 sample directions (Sec. 4.2): the normal map (its texel
// under the pixel, GL_NEAREST, or a bilinear blend, GL_LINEAR; repeat) through the interpolated
// tangent frame gives the meso normal in the contact frame,
// then its ploughing vector g (ploughing.glsl) and mu_k = gain * max(0, g . d_k), scaled by
// u_scale (1 / mu_max for RGBA8 targets, 1 for float targets). Target 0 marks coverage.
// GROUPS (1..7) is defined by the program that includes this file. GROUPS 0 writes the
// fragments themselves for a friction model that reads more than P's sums: (g, the surface's
// height at the fragment, its depth key) into one RGBA32F target, read back to the CPU.
in vec2 v_uv;
in vec3 v_tangent;
in vec3 v_bitangent;
in vec3 v_normal;
flat in vec4 v_edge0;
flat in vec4 v_edge1;
flat in vec4 v_edge2;
flat in vec2 v_tile_origin;  // the tile's lower-left corner in the atlas (window pixels)
flat in float v_side;

uniform sampler2D u_normal_map;
uniform sampler2D u_mask;
uniform bool u_has_map;
uniform bool u_has_mask;
uniform float u_mu_max;
uniform float u_scale;
uniform float u_half_width;
uniform float u_pixel;
// Texels the nearest reading moves its lookup along +u and +v (the CPU's kNearestTexelNudge; 0
// for the bilinear reading).
uniform float u_texel_nudge;
uniform vec2 u_directions[28];  // this pass's directions, GROUPS x 4 used

#if GROUPS == 0
in float v_depth;
uniform sampler2D u_heights;
uniform bool u_has_heights;
layout(location = 0) out vec4 o_fragment;
#else
layout(location = 0) out vec4 o_coverage;
layout(location = 1) out vec4 o_mu0;
#endif
#if GROUPS > 1
layout(location = 2) out vec4 o_mu1;
#endif
#if GROUPS > 2
layout(location = 3) out vec4 o_mu2;
#endif
#if GROUPS > 3
layout(location = 4) out vec4 o_mu3;
#endif
#if GROUPS > 4
layout(location = 5) out vec4 o_mu4;
#endif
#if GROUPS > 5
layout(location = 6) out vec4 o_mu5;
#endif
#if GROUPS > 6
layout(location = 7) out vec4 o_mu6;
#endif

// Four coefficients of group `k` (directions 4k .. 4k + 3).
vec4 group(vec2 g, float gain, int k) {
  vec4 mu;
  for (int c = 0; c < 4; ++c) mu[c] = max(0.0, dot(g, u_directions[4 * k + c]));
  return mu * (gain * u_scale);
}

// The CPU sampler's exact coverage test of one edge at contact-frame point p (top-left rule).
bool insideEdge(vec4 e, vec2 p) {
  float value = e.x * p.x + e.y * p.y + e.z;
  return value > 0.0 || (value == 0.0 && e.w > 0.5);
}

void main() {
  // The pixel centre in the contact frame: the source triangle's edges decide coverage there,
  // not the rasteriser's snapped vertices (a centre within 1/256 pixel of an edge).
  vec2 centre = (gl_FragCoord.xy - v_tile_origin) * u_pixel - vec2(u_half_width);
  if (!insideEdge(v_edge0, centre) || !insideEdge(v_edge1, centre) ||
      !insideEdge(v_edge2, centre)) {
    discard;
  }
  vec3 m_tangent = vec3(0.0, 0.0, 1.0);
  if (u_has_map) {
    m_tangent = texture(u_normal_map, v_uv + u_texel_nudge / vec2(textureSize(u_normal_map, 0))).xyz;
  }
  vec3 m = v_tangent * m_tangent.x + v_bitangent * m_tangent.y + v_normal * m_tangent.z;
  vec2 g = ploughingVector(m, v_side, u_mu_max);
  float gain = 1.0;
  if (u_has_mask) {
    gain = max(texture(u_mask, v_uv + u_texel_nudge / vec2(textureSize(u_mask, 0))).r, 0.0);
  }
#if GROUPS == 0
  float height = u_has_heights ? texture(u_heights, v_uv).r : 0.0;
  o_fragment = vec4(gain * g, height, v_depth);
#else
  o_coverage = vec4(1.0);
  o_mu0 = group(g, gain, 0);
#endif
#if GROUPS > 1
  o_mu1 = group(g, gain, 1);
#endif
#if GROUPS > 2
  o_mu2 = group(g, gain, 2);
#endif
#if GROUPS > 3
  o_mu3 = group(g, gain, 3);
#endif
#if GROUPS > 4
  o_mu4 = group(g, gain, 4);
#endif
#if GROUPS > 5
  o_mu5 = group(g, gain, 5);
#endif
#if GROUPS > 6
  o_mu6 = group(g, gain, 6);
#endif
}
