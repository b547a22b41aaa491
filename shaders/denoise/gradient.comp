// gradient.comp: the temporal gradient of A-SVGF (Schied et al. 2018) at 1/3 resolution. Per 3x3
// stratum with a forward-projected sample (gradient_prev.y = index 0..8 of the pixel in the
// stratum, -1 = none): delta = l_cur - l_prev and Delta = max(l_cur, l_prev). l_cur is the
// re-shaded sample's luminance: with CURRENT_GIVEN gradient_prev.z (the renderer shaded it apart;
// negative or not finite: missing), else the luminance of the sample's pixel of `illumination`.
// Strata without a usable sample write (0, 0): they add nothing to either sum of the gradient
// a-trous, so the ratio |delta^|/Delta^ the temporal pass uses is the one of the samples that exist
// (common/gradient_sample.glsl). Where l_cur is given and the gradient a-trous runs, its first
// iteration computes the gradient from the samples itself, and this pass does not run.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/compute.glsl"
#include "common/gradient_sample.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;  // full resolution
  uint height;
  uint gradient_width;  // ceil(width / 3)
  uint gradient_height;
  uint luminance_in_alpha;  // 1: illumination.a holds the luminance (pathtrace's SPLIT_SPECULAR), -1 missing
  uint pad0;
  uint pad1;
  uint pad2;
} params;
#ifndef CURRENT_GIVEN
layout(set = 0, binding = 1) uniform texture2D illumination;
#endif
layout(set = 0, binding = 2) uniform texture2D gradient_prev;
layout(set = 0, binding = 3, rgba16f) writeonly uniform image2D gradient;

void main() {
  ivec2 s = invocation_pixel();
  if (!inside(s, params.gradient_width, params.gradient_height)) return;
  vec4 prev = texelFetch(gradient_prev, s, 0);
#ifdef CURRENT_GIVEN
  const vec2 result = gradient_of_given_sample(s, prev, params.width, params.height, params.luminance_in_alpha != 0u);
#else
  vec2 result = vec2(0.0);
  ivec2 p;
  if (gradient_sample_pixel(s, prev, params.width, params.height, params.luminance_in_alpha != 0u, p)) {
    vec4 c = texelFetch(illumination, p, 0);
    bool usable = params.luminance_in_alpha != 0u ? c.a >= 0.0 : !any_not_finite(c.rgb);
    float l_cur = params.luminance_in_alpha != 0u ? c.a : luminance(clamp_sample(c.rgb));
    if (usable) result = gradient_of_sample(prev.x, l_cur);
  }
#endif
  imageStore(gradient, s, vec4(result, 0.0, 0.0));
}
