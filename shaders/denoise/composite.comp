// composite.comp: re-modulates the filtered illumination with the albedo and writes HDR radiance
// (RGBA32F, or RGBA16F with HDR_HALF) and the tonemapped sRGB display image (RGBA8 unorm)
// (common/composite.glsl). The SPLIT variant adds the filtered specular signal times its own albedo
// (pathtrace's SPLIT_SPECULAR). The LOCAL_MEAN variant applies the displayed colour's local-mean
// correction first (local_mean.comp's last pass, which then runs only where something reads its
// image), so that the corrected colour is not written and read back. ILLUMINATION_RGB9E5 reads the illumination as RGB9E5 from an R32UI
// image (a last a-trous iteration's RGB9E5_OUT: common/filter_texel.glsl).
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
  int local_mean_radius;  // LOCAL_MEAN: the correction's window, in blocks (local_mean.comp)
  int local_mean_block;   // LOCAL_MEAN: pixels a block's side
} params;
#ifdef ILLUMINATION_RGB9E5
layout(set = 0, binding = 1) uniform utexture2D illumination;
#else
layout(set = 0, binding = 1) uniform texture2D illumination;
#endif
#define ALBEDO_BINDING 2
#include "common/albedo.glsl"  // float, or RGB9E5 words with ALBEDO_RGB9E5
#ifdef HDR_HALF
layout(set = 0, binding = 3, rgba16f) writeonly uniform image2D hdr;
#else
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D hdr;
#endif
layout(set = 0, binding = 4, rgba8) writeonly uniform image2D display;
// SanitizeCounters (temporal.comp declares the same block): composite counts zeroed_outputs.
#ifdef SPLIT
layout(set = 0, binding = 6) uniform texture2D specular;
layout(set = 0, binding = 7) uniform texture2D specular_albedo;
#endif
#ifdef LOCAL_MEAN
layout(set = 0, binding = 8) uniform texture2D box_means;  // local_mean.comp's BOX pass
#define LOCAL_MEAN_READS_BOX_MEANS
#include "common/local_mean.glsl"
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
#ifdef ILLUMINATION_RGB9E5
  vec4 light = vec4(unpack_rgb9e5(texelFetch(illumination, p, 0).r), 0.0);
#else
  vec4 light = texelFetch(illumination, p, 0);
#endif
#ifdef LOCAL_MEAN
  const ivec2 size = ivec2(params.width, params.height);
  light = local_mean_corrected(light, local_mean_scale(p, size, params.local_mean_block, params.local_mean_radius, true));
#endif
  composite_pixel(p, light.rgb);
}
