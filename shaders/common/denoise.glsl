// common/denoise.glsl: edge-stopping weights and kernels of the denoiser passes (SVGF, Schied et
// al. 2017, eq. for w_z, w_n, w_l as in the seed document). CPU twin:
// pipeline/reference/denoise_math.hpp (same constants, same guards).
#ifndef ASVGF_COMMON_DENOISE_GLSL
#define ASVGF_COMMON_DENOISE_GLSL

#include "common/color.glsl"
#include "common/octahedral.glsl"

// depth_normal texel: x linear view depth (0 = no hit), y max(|dz/dx|, |dz/dy|), zw octahedral normal.
struct Surface {
  float z;
  float dz;
  vec3 n;
};
Surface surface_from(vec4 t) { return Surface(t.x, t.y, oct_decode(t.zw)); }
bool hit(Surface s) { return s.z > 0.0; }

// Lower bound on the depth tolerance, relative to depth: a plane facing the camera has a zero
// gradient, and 0/0 must not happen.
const float kDepthEpsRel = 1e-3;
// SVGF's guard on the luminance weight's denominator.
const float kLumEps = 1e-10;

// w_z = exp(-|z_p - z_q| / (sigma_z |<grad z(p), p - q>|)); with the scalar gradient g the inner
// product is bounded by g (|dx| + |dy|) (exact on a plane), hence `dist_l1`.
float weight_depth(Surface p, Surface q, float dist_l1, float sigma_z) {
  if (!hit(q)) return 0.0;
  float tolerance = max(sigma_z * p.dz * dist_l1, kDepthEpsRel * p.z);
  return exp(-abs(p.z - q.z) / tolerance);
}

// w_n = max(0, <n_p, n_q>)^sigma_n
float weight_normal(Surface p, Surface q, float sigma_n) {
  return pow(clamp(dot(p.n, q.n), 0.0, 1.0), sigma_n);
}

// w_l = exp(-|l_p - l_q| / (sigma_l sqrt(g3x3(Var)) + eps))
float weight_luminance(float lp, float lq, float sigma_l, float std_dev) {
  return exp(-abs(lp - lq) / (sigma_l * std_dev + kLumEps));
}

// 1D kernel taps: B3 spline (1/16, 1/4, 3/8, 1/4, 1/16) for |i| <= 2; box of 3 for |i| <= 1.
float b3spline(int i) { return i == 0 ? 0.375 : (abs(i) == 1 ? 0.25 : 0.0625); }
// Binomial (1/4, 1/2, 1/4): the 3x3 low-pass used by the variance prefilter and gradient a-trous.
float binomial3(int i) { return i == 0 ? 0.5 : 0.25; }

// Reprojection consistency of a history tap (SVGF/Falcor style, relative depth tolerance).
const float kReprojDepthRel = 0.02;
const float kReprojDepthGrad = 4.0;
const float kReprojNormalCos = 0.9;
bool reprojection_consistent(Surface cur, Surface prev) {
  if (!hit(prev)) return false;
  if (abs(cur.z - prev.z) > kReprojDepthRel * cur.z + kReprojDepthGrad * cur.dz) return false;
  return dot(cur.n, prev.n) >= kReprojNormalCos;
}

#endif
