// composite.comp: re-modulates the filtered illumination with the albedo and writes HDR radiance
// (RGBA32F) and the tonemapped sRGB display image (RGBA8 unorm) (common/composite.glsl). The SPLIT
// variant adds the filtered specular signal times its own albedo (pathtrace's SPLIT_SPECULAR).
// Where a chain ends in a packed a-trous iteration and has one signal, that iteration composites
// itself (atrous.comp, COMPOSITE) and this pass does not run.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/color.glsl"
#include "common/compute.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  float exposure;  // multiplier applied before the tone curve
  uint tonemap;    // 0: clamp, 1: ACES (Narkowicz)
} params;
layout(set = 0, binding = 1) uniform texture2D illumination;
layout(set = 0, binding = 2) uniform texture2D albedo;
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D hdr;
layout(set = 0, binding = 4, rgba8) writeonly uniform image2D display;
// SanitizeCounters (temporal.comp declares the same block): composite counts zeroed_outputs.
#ifdef SPLIT
layout(set = 0, binding = 6) uniform texture2D specular;
layout(set = 0, binding = 7) uniform texture2D specular_albedo;
#endif
layout(set = 0, binding = 5) buffer Counters {
  uint nan_samples;
  uint inf_samples;
  uint clamped_samples;
  uint zeroed_outputs;
} counters;

#include "common/composite.glsl"

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  composite_pixel(p, texelFetch(illumination, p, 0).rgb);
}
