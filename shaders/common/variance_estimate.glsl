// common/variance_estimate.glsl: SVGF's per-pixel luminance variance (sec. 4.2) from the temporal
// pass's colour and moments, for the variance pass (denoise/variance.comp) and for the first a-trous
// iteration that estimates it while loading its tile (denoise/atrous.comp, FUSED_VARIANCE). The
// including shader declares `params` (width, height, sigma_z, sigma_n, sigma_l, min_history), the
// textures `integrated` (R32UI: RGB9E5 words, common/color.glsl), `moments` (R32UI: E[l], sqrt(Var[l])
// and n in one word, common/denoise.glsl's pack_moments) and `depth_normal`, and the albedo (what the
// signal is re-modulated by: common/albedo.glsl). With at least min_history frames of history: the
// temporal estimate Var[l]; with less, a 7x7 edge-aware spatial estimate of the moments (and of the
// colour), boosted by min_history / n as in Falcor's SVGF, except that with one frame of history the
// moments are weighted by depth and normal only (see below). The 7x7 neighbours are fetched
// directly, only by pixels with a short history.
#ifndef ASVGF_COMMON_VARIANCE_ESTIMATE_GLSL
#define ASVGF_COMMON_VARIANCE_ESTIMATE_GLSL

#include "common/denoise.glsl"

const int kVarianceRadius = 3;

vec3 integrated_color(ivec2 q) { return unpack_rgb9e5(texelFetch(integrated, q, 0).x); }

// Colour and variance of pixel p (inside the image) with surface `center`, clamped to fp16's range.
vec4 estimate_color_variance(ivec2 p, Surface center) {
  vec3 color = integrated_color(p);
  vec3 mn = unpack_moments(texelFetch(moments, p, 0).x);
  Moments m = moments_from_stored(mn.xy);
  float n = mn.z;
  float variance = m.variance;

  if (hit(center) && n > 0.0 && n < params.min_history) {
    // The luminance weight has no variance to scale by, so it compares radiance, in which sigma_l
    // is set: the neighbours' light re-modulated by this pixel's albedo. Comparing the demodulated
    // signal made the weight 1/albedo times stricter, and demodulation cost error on untextured
    // surfaces where it should change nothing (docs/quality.md).
    vec3 ap = albedo_at(p);
    float lp = luminance(ap * color);
    vec3 sum_c = vec3(0.0);
    vec3 sum_m = vec3(0.0);  // the neighbours' mixture (common/denoise.glsl: mixture_term)
    float sum_w = 0.0, sum_wm = 0.0;
    for (int dy = -kVarianceRadius; dy <= kVarianceRadius; ++dy) {
      for (int dx = -kVarianceRadius; dx <= kVarianceRadius; ++dx) {
        float w = 1.0, w_surface = 1.0;
        vec3 cq = color;
        Moments mq = m;
        if (dx != 0 || dy != 0) {
          ivec2 q = p + ivec2(dx, dy);
          if (q.x < 0 || q.y < 0 || !inside(q, params.width, params.height)) continue;
          vec3 other_m = unpack_moments(texelFetch(moments, q, 0).x);
          if (!(other_m.z > 0.0)) continue;  // a neighbour without history is not part of the estimate
          mq = moments_from_stored(other_m.xy);
          cq = integrated_color(q);
          Surface other = surface_from(texelFetch(depth_normal, q, 0));
          float dist = float(abs(dx) + abs(dy));
          w_surface = weight_depth(center, other, dist, params.sigma_z) * weight_normal(center, other, params.sigma_n);
          // No variance yet: the luminance weight uses sigma_l alone (std dev taken as 1).
          w = w_surface * weight_luminance(lp, luminance(ap * cq), params.sigma_l, 1.0);
        }
        sum_c += w * cq;
        sum_w += w;
        // One frame of history: a pixel's own moments hold no variance (Var[l] = 0), so the
        // estimate is the spread of its neighbours' luminance, which the luminance weight would
        // cut exactly where it is large: a firefly (l >> sigma_l) would get variance 0 and survive
        // the a-trous untouched (glossy first frame: relMSE 0.30 against 0.028 at 192x192).
        float wm = n < 1.5 ? w_surface : w;
        sum_m += wm * mixture_term(mq);
        sum_wm += wm;
      }
    }
    color = sum_c / sum_w;
    variance = mixture_moments(sum_m / sum_wm).variance * (params.min_history / n);
  }
  return clamp_fp16(vec4(color, variance));
}

#endif
