// common/denoise.glsl: edge-stopping weights and kernels of the denoiser passes (SVGF, Schied et
// al. 2017, eq. for w_z, w_n, w_l as in the seed document). CPU twin:
// pipeline/cpu_oracle/denoise_math.hpp (same constants, same guards).
#ifndef ASVGF_COMMON_DENOISE_GLSL
#define ASVGF_COMMON_DENOISE_GLSL

#include "common/color.glsl"
#include "common/depth_normal.glsl"
#include "common/random.glsl"

// A pixel's surface: linear view depth (0 = no hit), max(|dz/dx|, |dz/dy|), unit normal.
struct Surface {
  float z;
  float dz;
  vec3 n;
};
// From the depth_normal texel (common/depth_normal.glsl).
Surface surface_from(uvec4 t) { return Surface(depth_normal_depth(t), depth_normal_gradient(t), depth_normal_normal(t)); }
bool hit(Surface s) { return s.z > 0.0; }

// The luminance moments and the history length as the temporal pass stores them, one R32UI word a
// pixel (4 bytes instead of RGBA16F's 8; GLES 3.1 stores no rg16f or r16f), written and read
// bilinearly once a frame and read by the variance estimate:
//   bits  0-14  E[l]: the bits of its half float without the sign (E[l] >= 0), rounded to nearest
//   bits 15-23  sqrt(Var[l]): the top 9 of its half's 15 bits (5 exponent, 4 mantissa bits), rounded to
//               nearest: within 1/32 relative. The standard deviation only scales edge-stopping
//               weights and the next frame's blend, where that is far below the sample's own noise.
//   bits 24-31  n: 0 (no history) or 1 + its 4 exponent and 4 mantissa bits for n in [1, 61440]:
//               integers exact to 32 (the default history_cap), fractions kept below, rounded to
//               nearest (within 1/32 relative). Above 32 a step is more than one frame, so the
//               rounding there is stochastic (`n_rounding`, within 1/16): n + 1 grows by one on
//               average instead of stopping (at 64 if rounded to nearest).
// fp16 cannot hold E[l^2] above l = 256, but it holds the standard deviation of any luminance the
// clamped samples can have (<= fp16 max / 2). The passes blend the mean and the variance (Chan et
// al.'s update, below), so a converged pixel's variance is not E[l^2] - E[l]^2's difference of two
// large numbers. CPU twin: tests/pipeline/denoise_harness.hpp's pack_moments.
struct Moments {
  float mean;
  float variance;
};
Moments moments_from_stored(vec2 stored) { return Moments(stored.x, stored.y * stored.y); }
vec2 moments_to_stored(Moments m) { return vec2(m.mean, sqrt(max(0.0, m.variance))); }
// (E[l], sqrt(Var[l]), n) from the word.
vec3 unpack_moments(uint word) {
  // The two halves rebuilt side by side and converted at once: the temporal pass unpacks four words
  // a pixel, in a pass bound by its instructions (docs/performance.md, "The three words, timed").
  const vec2 halves = unpackHalf2x16((word & 0x7fffu) | ((word & 0x00ff8000u) << 7));
  const uint code = word >> 24;
  const float n = code == 0u ? 0.0 : uintBitsToFloat(((code - 1u) << 19) + (127u << 23));
  return vec3(halves, n);
}
// The word for stored = moments_to_stored(m) (finite) and n; n's last kept bit is rounded up where
// its dropped bits exceed 1 - rounding (0.5: to nearest).
uint pack_moments(vec2 stored, float n, float rounding) {
  const uint mean = packHalf2x16(vec2(round_to_half(clamp(stored.x, 0.0, kFp16Max)), 0.0)) & 0x7fffu;
  const uint sd_half = packHalf2x16(vec2(round_to_half(clamp(stored.y, 0.0, kFp16Max)), 0.0)) & 0x7fffu;
  // Ties to even on the bits; 0x1ef is the largest finite 9-bit pattern (0x7c00 >> 6 would be Inf).
  const uint sd = min((sd_half + 0x1fu + ((sd_half >> 6) & 1u)) >> 6, 0x1efu);
  uint code = 0u;
  if (n > 0.0) {
    const uint bits = floatBitsToUint(clamp(n, 1.0, 61440.0)) - (127u << 23);
    code = min((bits + uint(rounding * 524288.0)) >> 19, 254u) + 1u;
  }
  return mean | (sd << 15) | (code << 24);
}
// Where n's kept bits step by more than one frame (n >= 32) and n falls between two of them, a
// stochastic rounding of it from a hash; elsewhere, to nearest (exact where n is kept: the default
// cap 32, where every converged pixel sits, needs no hash). Deterministic: the same pixel and
// sample give the same rounding.
float n_rounding(float n, uint seed) {
  const bool between = n >= 32.0 && (floatBitsToUint(n) & 0x7ffffu) != 0u;
  return between ? float(pcg_hash(seed) >> 8) * (1.0 / 16777216.0) : 0.5;
}
// (1 - a) history + a sample, as distributions: the mean moves by a d and the variance is
// (1 - a) (Var_h + a d^2), d = l - mean_h (exact; no cancellation).
Moments blend_moments(Moments h, float l, float a) {
  const float d = l - h.mean;
  return Moments(h.mean + a * d, (1.0 - a) * (h.variance + a * d * d));
}
// A weighted mixture of distributions: sum w * mixture_term(m) over them, divide by the weights'
// sum, and mixture_moments gives the mixture's mean and variance (the parts' mean variance plus
// the spread of their means).
vec3 mixture_term(Moments m) { return vec3(m.mean, m.variance, m.mean * m.mean); }
Moments mixture_moments(vec3 mean_terms) {
  return Moments(mean_terms.x, mean_terms.y + max(0.0, mean_terms.z - mean_terms.x * mean_terms.x));
}

// Lower bound on the depth tolerance, relative to depth: a plane facing the camera has a zero
// gradient, and 0/0 must not happen.
const float kDepthEpsRel = 1e-3;
// SVGF's guard on the luminance weight's denominator.
const float kLumEps = 1e-10;

// w_z = exp(-|z_p - z_q| / (sigma_z |<grad z(p), p - q>|)); with the scalar gradient g the inner
// product is bounded by g (|dx| + |dy|) (exact on a plane), hence `dist_l1`.
// One return in each function a tap loop calls: see atrous_tap_weight.
float weight_depth(Surface p, Surface q, float dist_l1, float sigma_z) {
  float tolerance = max(sigma_z * p.dz * dist_l1, kDepthEpsRel * p.z);
  return hit(q) ? exp(-abs(p.z - q.z) / tolerance) : 0.0;
}

// A-SVGF's temporal gradient response: lambda = min(1, antilag |delta^| / Delta^), 0 where Delta^ = 0;
// g = (delta^, Delta^). The temporal pass's, and the debug view's picture of it.
float gradient_response(vec2 g, float antilag) { return g.y > 0.0 ? min(1.0, antilag * abs(g.x) / g.y) : 0.0; }

// w_n = max(0, <n_p, n_q>)^sigma_n
float weight_normal(Surface p, Surface q, float sigma_n) {
  return pow(clamp(dot(p.n, q.n), 0.0, 1.0), sigma_n);
}

// w_l = exp(-|l_p - l_q| / (sigma_l sqrt(g3x3(Var)) + eps))
float weight_luminance(float lp, float lq, float sigma_l, float std_dev) {
  return exp(-abs(lp - lq) / (sigma_l * std_dev + kLumEps));
}

// The same three weights as one exp2 for the a-trous taps, whose arithmetic bounds the pass: the
// divisions are hoisted out of the tap loop (AtrousScales, per pixel) and pow(c, s) is exp2(s log2 c).
// The CPU reference keeps the three separate functions above; the results agree to fp32 rounding
// (the a-trous tests' tolerance). A NaN cosine gives weight 0 where sigma_n > 0 (pack_surface never
// lets one in).
const float kLog2e = 1.4426950408889634;
struct AtrousScales {
  vec4 depth;  // log2(e) / w_z's tolerance at L1 tap distance step * (1, 2, 3, 4)
  float luminance;  // log2(e) / (sigma_l std_dev + eps)
};
AtrousScales atrous_scales(Surface p, int step, float sigma_z, float sigma_l, float std_dev) {
  const vec4 tolerance = max(sigma_z * p.dz * float(step) * vec4(1.0, 2.0, 3.0, 4.0), vec4(kDepthEpsRel * p.z));
  return AtrousScales(kLog2e / tolerance, kLog2e / (sigma_l * std_dev + kLumEps));
}
// w_z w_n w_l of a tap at L1 distance l1 (in steps, 1..4) with depth zq (0: no hit, weight 0).
// One return: an early one becomes a one-trip loop when inlined, which NVIDIA's OpenGL SPIR-V front
// end compiles as a loop (docs/performance.md).
float atrous_tap_weight(Surface p, float lp, float zq, vec3 nq, float lq, int l1, float sigma_n, AtrousScales s) {
  // The special cases as one clamp and one select (fewer instructions a tap: docs/performance.md):
  // a cosine rounded above 1 counts as 1, and log2 never sees 0 or less (undefined in GLSL).
  const float cos_pq = dot(p.n, nq);
  const float log2_wn = sigma_n * log2(clamp(cos_pq, 1e-30, 1.0));
  const float w = exp2(log2_wn - abs(p.z - zq) * s.depth[l1 - 1] - abs(lp - lq) * s.luminance);
  // No hit, or a normal facing away: pow(0, sigma_n) = 0 (pow(c, 0) = 1); a NaN cosine is not > 0.
  return zq > 0.0 && (cos_pq > 0.0 || sigma_n == 0.0) ? w : 0.0;
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
  return hit(prev) && !(abs(cur.z - prev.z) > kReprojDepthRel * cur.z + kReprojDepthGrad * cur.dz) &&
         dot(cur.n, prev.n) >= kReprojNormalCos;
}

#endif
