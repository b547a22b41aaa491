// common/composite.glsl: re-modulation and display of one pixel, for the composite pass
// (denoise/composite.comp) and for the last a-trous iteration that does it itself
// (denoise/atrous.comp, COMPOSITE). The including shader declares `params` (exposure, tonemap), the
// albedo (common/albedo.glsl), the textures `specular` and `specular_albedo` with SPLIT, the images `hdr` (rgba32f, or
// rgba16f with HDR_HALF) and `display` (rgba8) and the SanitizeCounters buffer `counters`.
// Re-modulates the filtered illumination with the albedo (the inverse of the path tracer's
// demodulation radiance / max(albedo, 1e-3)), writes HDR radiance and a display image: exposure,
// then the ACES filmic fit of Narkowicz (2015) or a plain clamp, then the sRGB transfer function.
// Non-finite radiance (possible with the raw and reference methods, which skip the sanitising
// temporal pass) is written as 0 and counted, so that no output ever holds NaN or Inf.
#ifndef ASVGF_COMMON_COMPOSITE_GLSL
#define ASVGF_COMMON_COMPOSITE_GLSL

#include "common/color.glsl"

vec3 aces_narkowicz(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

float srgb_encode(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }

// `light`: pixel p's filtered (demodulated) illumination.
void composite_pixel(ivec2 p, vec3 light) {
  vec3 radiance = light * max(albedo_at(p), vec3(1e-3));
#ifdef SPLIT
  radiance += texelFetch(specular, p, 0).rgb * max(texelFetch(specular_albedo, p, 0).rgb, vec3(1e-3));
#endif
  if (any_not_finite(radiance)) {
    radiance = vec3(0.0);
    atomicAdd(counters.zeroed_outputs, 1u);
  }
#ifdef HDR_HALF
  // Rounded to the nearest half, within its range: a store's own rounding may be toward zero
  // (common/color.glsl), and a radiance past 65504 (an albedo above 1) would store as Inf. The
  // clamped form's four integer operations a channel (below 2^-14 the last bit is the store's): the
  // general one's tests and the RGB9E5 decode had cost the composite 0.003 ms at 1080p on an H100,
  // the clamped form won 0.002 of it back (docs/performance.md).
  imageStore(hdr, p, round_to_half_clamped(clamp_fp16(vec4(radiance, 1.0))));
#else
  imageStore(hdr, p, vec4(radiance, 1.0));
#endif
  vec3 x = max(radiance * params.exposure, vec3(0.0));
  vec3 mapped = params.tonemap == 1u ? aces_narkowicz(x) : clamp(x, 0.0, 1.0);
  imageStore(display, p, vec4(srgb_encode(mapped.r), srgb_encode(mapped.g), srgb_encode(mapped.b), 1.0));
}

#endif
