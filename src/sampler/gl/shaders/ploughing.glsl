// The per-fragment friction model in GLSL (SPEC 2, Eqs. 3 to 6), the same form as
// friction/fragment_model.cpp: a fragment's ploughing vector g (components along t and b) with
// mu_d = max(0, g . d). `side` is +1 for surface B (facing +n) and -1 for A (facing -n); m is
// the meso normal in the contact frame (any length).
//   unclamped: g = side (2/pi) m_tb / (side m_z)
//   clamped (steeper than mu_max, or facing away): g = side mu_max m_tb / |m_tb|
const float kTwoOverPi = 0.63661977236758134;

vec2 ploughingVector(vec3 m, float side, float mu_max) {
  float height = side * m.z;
  vec2 tangential = m.xy;
  float radius = length(tangential);
  if (height > 0.0 && kTwoOverPi * radius <= mu_max * height) {
    return (side * kTwoOverPi / height) * tangential;
  }
  if (!(radius > 0.0)) return vec2(0.0);
  return (side * mu_max / radius) * tangential;
}
