// Eq. 8 on the GPU: for each contact of the pass (a work group), each of its 16 lanes sums,
// over every 16th row of the pixels that both of its tiles cover (A in tile 2c, B in tile
// 2c + 1), each direction's coefficient of either surface, and counts those pixels. The CPU
// adds the 16 lanes' sums in lane order. No lane waits for another (no shared memory), which
// keeps the shader as fast on a software renderer as on a GPU. A dispatch reads GROUPS (1..8,
// defined by the program) groups of four directions from u_first_group on.
layout(local_size_x = 16) in;

uniform sampler2D u_coverage;
uniform sampler2D u_mu[GROUPS];
uniform int u_resolution;  // R: a tile's side
uniform int u_per_row;     // tiles per atlas row
uniform int u_directions;  // N: the layout of the sums
uniform int u_first_group;
uniform float u_scale;  // mu per unit of the targets: mu_max for RGBA8, 1 for float targets

// Per contact and lane: |P| of its rows, the N sums of surface A, then the N sums of surface B.
layout(std430, binding = 0) writeonly buffer Sums {
  float sums[];
};

ivec2 tileOrigin(int tile) {
  return ivec2(tile % u_per_row, tile / u_per_row) * u_resolution;
}

void main() {
  int c = int(gl_WorkGroupID.x);
  int lane = int(gl_LocalInvocationID.x);
  ivec2 origin_a = tileOrigin(2 * c);
  ivec2 origin_b = tileOrigin(2 * c + 1);
  vec4 a[GROUPS];
  vec4 b[GROUPS];
  for (int g = 0; g < GROUPS; ++g) {
    a[g] = vec4(0.0);
    b[g] = vec4(0.0);
  }
  float count = 0.0;
  for (int j = lane; j < u_resolution; j += 16) {
    for (int i = 0; i < u_resolution; ++i) {
      ivec2 q = ivec2(i, j);
      if (texelFetch(u_coverage, origin_a + q, 0).r == 0.0 ||
          texelFetch(u_coverage, origin_b + q, 0).r == 0.0) {
        continue;
      }
      count += 1.0;
      for (int g = 0; g < GROUPS; ++g) {
        a[g] += texelFetch(u_mu[g], origin_a + q, 0);
        b[g] += texelFetch(u_mu[g], origin_b + q, 0);
      }
    }
  }
  int base = (c * 16 + lane) * (1 + 2 * u_directions);
  if (u_first_group == 0) sums[base] = count;
  for (int g = 0; g < GROUPS; ++g) {
    int k = 4 * (u_first_group + g);
    for (int i = 0; i < 4; ++i) {
      sums[base + 1 + k + i] = a[g][i] * u_scale;
      sums[base + 1 + u_directions + k + i] = b[g][i] * u_scale;
    }
  }
}
