// variance.comp: per-pixel luminance variance for the a-trous filter (SVGF sec. 4.2,
// common/variance_estimate.glsl). Output: rgb colour, a variance (clamped to fp16 max). The
// denoiser runs it only where the first a-trous iteration cannot estimate the variance itself (the
// box kernel, a single iteration, images too large for the packed texels) and for the variance
// debug view. A shared-memory tile of the 7x7 neighbours, loaded by any workgroup with one
// short-history pixel, cost its barriers and shared memory in every workgroup: it lost more on
// frames with long histories than it saved where every pixel needs the estimate
// (docs/performance.md).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/compute.glsl"
#include "common/denoise.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  float sigma_z;
  float sigma_n;
  float sigma_l;
  float min_history;  // SVGF: 4
} params;
layout(set = 0, binding = 1) uniform utexture2D integrated;  // RGB9E5 words (temporal.comp's COLOR_RGB9E5)
layout(set = 0, binding = 2) uniform utexture2D moments;  // E[l], sqrt(Var[l]), history length: pack_moments
layout(set = 0, binding = 3) uniform utexture2D depth_normal;
layout(set = 0, binding = 4, rgba16f) writeonly uniform image2D color_variance;
#define ALBEDO_BINDING 5  // what the signal is re-modulated by: float, or RGB9E5 words (ALBEDO_RGB9E5)
#include "common/albedo.glsl"

#include "common/variance_estimate.glsl"

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  imageStore(color_variance, p, round_to_half(estimate_color_variance(p, surface_from(texelFetch(depth_normal, p, 0)))));
}
