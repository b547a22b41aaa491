// composite.comp: re-modulates the filtered illumination with the albedo (the inverse of the
// path tracer's demodulation radiance / max(albedo, 1e-3)), writes HDR radiance (RGBA32F) and a
// display image: exposure, then the ACES filmic fit of Narkowicz (2015) or a plain clamp, then the
// sRGB transfer function, stored as RGBA8 unorm. Non-finite radiance (possible with the raw and
// reference methods, which skip the sanitising temporal pass) is written as 0 and counted, so that
// no output ever holds NaN or Inf. The SPLIT variant adds the filtered specular signal times its
// own albedo (pathtrace's SPLIT_SPECULAR).
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

vec3 aces_narkowicz(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

float srgb_encode(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  vec3 light = texelFetch(illumination, p, 0).rgb;
  vec3 radiance = light * max(texelFetch(albedo, p, 0).rgb, vec3(1e-3));
#ifdef SPLIT
  radiance += texelFetch(specular, p, 0).rgb * max(texelFetch(specular_albedo, p, 0).rgb, vec3(1e-3));
#endif
  if (any_not_finite(radiance)) {
    radiance = vec3(0.0);
    atomicAdd(counters.zeroed_outputs, 1u);
  }
  imageStore(hdr, p, vec4(radiance, 1.0));
  vec3 x = max(radiance * params.exposure, vec3(0.0));
  vec3 mapped = params.tonemap == 1u ? aces_narkowicz(x) : clamp(x, 0.0, 1.0);
  imageStore(display, p, vec4(srgb_encode(mapped.r), srgb_encode(mapped.g), srgb_encode(mapped.b), 1.0));
}
