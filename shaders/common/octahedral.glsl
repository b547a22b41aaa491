// common/octahedral.glsl: unit normals as two floats in [-1,1] (octahedral mapping, Meyer et al.
// 2010, "On floating-point normal vectors"). CPU twin: pipeline/cpu_oracle/octahedral.hpp.
#ifndef ASVGF_COMMON_OCTAHEDRAL_GLSL
#define ASVGF_COMMON_OCTAHEDRAL_GLSL

vec2 oct_sign(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

// n need not be normalised but must not be zero.
vec2 oct_encode(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  return n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * oct_sign(n.xy);
}

vec3 oct_decode(vec2 e) {
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * oct_sign(n.xy);
  return normalize(n);
}

#endif
