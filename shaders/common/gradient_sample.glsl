// common/gradient_sample.glsl: A-SVGF's temporal gradient of one 3x3 stratum from its
// forward-projected sample, gradient_prev (l_prev, index 0..8 of the pixel in the stratum or -1 for
// none[, l_cur]): delta = l_cur - l_prev and Delta = max(l_cur, l_prev), as fp16 holds them; (0, 0)
// without a usable sample, so that it adds nothing to either sum of the gradient a-trous. For the
// gradient pass (denoise/gradient.comp) and for the first gradient a-trous iteration, which
// computes the gradients of its taps from the samples itself where l_cur is given
// (denoise/gradient_atrous.comp, SAMPLES_IN).
#ifndef ASVGF_COMMON_GRADIENT_SAMPLE_GLSL
#define ASVGF_COMMON_GRADIENT_SAMPLE_GLSL

#include "common/color.glsl"

// Whether stratum s has a sample, and its pixel in a width x height image. l_prev < 0 with
// `luminance_in_alpha` (split signals): last frame's sample was missing.
// One exit (naga, the WGSL step, mistranslates early returns out of inlined functions).
bool gradient_sample_pixel(ivec2 s, vec4 prev, uint width, uint height, bool luminance_in_alpha, out ivec2 p) {
  const bool present = prev.y >= 0.0 && prev.y < 9.0 && !not_finite(prev.x) && (!luminance_in_alpha || prev.x >= 0.0);
  const int index = present ? int(prev.y) : 0;
  p = 3 * s + ivec2(index % 3, index / 3);
  return present && p.x < int(width) && p.y < int(height);
}

// (delta, Delta) of a sample with current luminance l_cur, as the gradient pass stores it.
vec2 gradient_of_sample(float l_prev, float l_cur) {
  const float clamped_prev = clamp(l_prev, 0.0, kFp16Max);
  return round_to_half(vec2(l_cur - clamped_prev, max(l_cur, clamped_prev)));
}

// The gradient of stratum s from its sample `prev` with l_cur given in prev.z (negative or not
// finite: missing).
vec2 gradient_of_given_sample(ivec2 s, vec4 prev, uint width, uint height, bool luminance_in_alpha) {
  ivec2 p;
  const bool present = gradient_sample_pixel(s, prev, width, height, luminance_in_alpha, p);
  const bool usable = present && prev.z >= 0.0 && !not_finite(prev.z);
  return usable ? gradient_of_sample(prev.x, min(prev.z, kFp16Max)) : vec2(0.0);
}

#endif
