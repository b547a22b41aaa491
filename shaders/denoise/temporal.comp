// temporal.comp: temporal accumulation of SVGF with A-SVGF's adaptive alpha.
// - Sanitises the 1-spp sample: a NaN/+-Inf component drops the sample (treated as missing) and
//   counts it in `counters` (SSBO atomics; image atomics are not portable); finite samples are
//   clamped to [0, fp16 max], and those at or above it counted.
// - Reprojects last frame's colour, moments and history length bilinearly through the motion
//   vector, each of the 4 taps tested for depth and normal consistency; fails (history reset) when
//   the valid taps' bilinear weight is below 0.01 (Falcor's SVGF).
// - alpha_i = (1 - lambda) alpha + lambda, lambda = min(1, antilag |delta^|/Delta^) (0 when Delta^ = 0)
//   with the ADAPTIVE variant; constant alpha otherwise. Moments use their own alpha the same way.
//   Short histories average uniformly: alpha_eff = max(alpha_i, 1/n); a gradient also shortens the
//   history, n = n_prev (1 - lambda) + 1, capped at history_cap.
// COLOR_RGB9E5 (a spatial chain's): the colour history read and the result written as RGB9E5 words
// (common/color.glsl), 4 bytes a pixel each instead of RGBA16F's 8, without the temporal variance,
// which the moments hold and the variance estimate reads from there. The EMA's result is its
// displayed colour and stays RGBA16F.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
#include "common/compute.glsl"
#include "common/denoise.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  uint gradient_width;
  uint gradient_height;
  float alpha;
  float moments_alpha;
  float history_cap;
  uint history_valid;  // 0: no history this frame (first frame, camera cut): reset everywhere
  float antilag;       // lambda = min(1, antilag |delta^| / Delta^)
  uint pad0;           // WGSL rounds a uniform block up to 16 bytes: the C++ struct must be that size
  uint pad1;
  uint pad2;
} params;
layout(set = 0, binding = 1) uniform texture2D illumination;
#define MOTION_BINDING 2  // float, or halves with MOTION_HALVES
#include "common/motion.glsl"
layout(set = 0, binding = 3) uniform utexture2D depth_normal;
layout(set = 0, binding = 4) uniform utexture2D prev_depth_normal;
#ifdef COLOR_RGB9E5
layout(set = 0, binding = 5) uniform utexture2D prev_color;
#else
layout(set = 0, binding = 5) uniform texture2D prev_color;
#endif
layout(set = 0, binding = 6) uniform utexture2D prev_moments;  // common/denoise.glsl: pack_moments
#ifdef ADAPTIVE
layout(set = 0, binding = 8) uniform texture2D gradient;
#endif
#ifdef COLOR_RGB9E5
layout(set = 0, binding = 9, r32ui) writeonly uniform uimage2D integrated;  // rgb
#else
layout(set = 0, binding = 9, rgba16f) writeonly uniform image2D integrated;  // rgb, the temporal variance
#endif
// E[l], sqrt(Var[l]) and the history length n in one word (common/denoise.glsl: pack_moments).
layout(set = 0, binding = 10, r32ui) writeonly uniform uimage2D moments;
// Since the buffer was cleared: samples dropped with a NaN component, with an Inf (no NaN), finite
// samples clamped to the fp16 maximum, and output pixels composite wrote as 0 (SanitizeCounters).
layout(set = 0, binding = 11) buffer Counters {
  uint nan_samples;
  uint inf_samples;
  uint clamped_samples;
  uint zeroed_outputs;
} counters;

struct History {
  vec3 color;
  Moments moments;
  float len;
  bool valid;
};

// One return and an unrolled tap loop without `continue`: an early return becomes a one-trip loop
// when inlined, and NVIDIA's OpenGL SPIR-V front end compiles loops as loops (docs/performance.md).
History reproject(ivec2 p, Surface cur) {
  History h = History(vec3(0.0), Moments(0.0, 0.0), 0.0, false);
  vec3 sum_m = vec3(0.0);  // the taps' mixture (common/denoise.glsl: mixture_term)
  vec4 mv = motion_at(p);
  vec2 prev = vec2(p) + 0.5 + mv.xy;
#ifdef VIRTUAL_MOTION
  bool through_reflection = mv.z > 0.5;
#endif
  vec2 pos = prev - 0.5;
  vec2 base = floor(pos);
  vec2 f = pos - base;
  // Far outside: nothing to fetch (also keeps ivec conversion in range).
  const bool fetch = params.history_valid != 0u && hit(cur) && !not_finite(prev.x) && !not_finite(prev.y) &&
                     !(base.x < -1.0 || base.y < -1.0 || base.x >= float(params.width) || base.y >= float(params.height));
  float sum_w = 0.0;
  if (fetch) {
    ivec2 b = ivec2(base);
    [[unroll]] for (int k = 0; k < 4; ++k) {
      ivec2 o = ivec2(k & 1, k >> 1);
      ivec2 q = b + o;
      float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
      if (q.x >= 0 && q.y >= 0 && inside(q, params.width, params.height) && w > 0.0) {
        vec3 mq = unpack_moments(texelFetch(prev_moments, q, 0).x);
        Surface before = surface_from(texelFetch(prev_depth_normal, q, 0));
#ifdef VIRTUAL_MOTION
        // Moved through a reflection's virtual point (motion.z = 1, specular_motion.comp), the
        // history lies on another part of the reflector, whose depth differs with the distance
        // moved: only the normal (flat reflectors) and a loose depth bound are tested there.
        const bool consistent =
            through_reflection
                ? hit(before) && !(abs(cur.z - before.z) > 0.1 * cur.z) && !(dot(cur.n, before.n) < kReprojNormalCos)
                : reprojection_consistent(cur, before);
#else
        const bool consistent = reprojection_consistent(cur, before);
#endif
        if (mq.z > 0.0 && consistent) {
#ifdef COLOR_RGB9E5
          h.color += w * unpack_rgb9e5(texelFetch(prev_color, q, 0).x);
#else
          h.color += w * texelFetch(prev_color, q, 0).rgb;
#endif
          sum_m += w * mixture_term(moments_from_stored(mq.xy));
          h.len += w * mq.z;
          sum_w += w;
        }
      }
    }
  }
  if (!(sum_w < 0.01)) {
    h.color /= sum_w;
    h.moments = mixture_moments(sum_m / sum_w);
    h.len /= sum_w;
    h.valid = true;
  } else {
    h = History(vec3(0.0), Moments(0.0, 0.0), 0.0, false);
  }
  return h;
}

float gradient_lambda(ivec2 p) {
#ifdef ADAPTIVE
  ivec2 s = min(p / 3, ivec2(params.gradient_width, params.gradient_height) - 1);
  return gradient_response(texelFetch(gradient, s, 0).xy, params.antilag);
#else
  return 0.0;
#endif
}

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  Surface cur = surface_from(texelFetch(depth_normal, p, 0));
  vec3 sample_rgb = texelFetch(illumination, p, 0).rgb;
  bool missing = any_not_finite(sample_rgb);
  if (missing) {
    if (any_nan(sample_rgb)) atomicAdd(counters.nan_samples, 1u);
    else atomicAdd(counters.inf_samples, 1u);
  }
  History h = reproject(p, cur);

  vec3 color;
  Moments m;
  float n;
  if (missing) {
    // The sample is dropped: keep what the history had, or nothing.
    color = h.valid ? h.color : vec3(0.0);
    m = h.valid ? h.moments : Moments(0.0, 0.0);
    n = h.valid ? min(h.len, params.history_cap) : 0.0;
  } else {
    // At the maximum counts too: a half-float input holds no more, so such a sample was most likely
    // clamped already (our renderer's path tracer clamps before it stores half floats).
    if (any(greaterThanEqual(sample_rgb, vec3(kFp16Max)))) atomicAdd(counters.clamped_samples, 1u);
    vec3 c = clamp_sample(sample_rgb);
    float l = luminance(c);
    if (h.valid) {
      float lambda = gradient_lambda(p);
      n = min(h.len * (1.0 - lambda) + 1.0, params.history_cap);
      float a = max((1.0 - lambda) * params.alpha + lambda, 1.0 / n);
      float am = max((1.0 - lambda) * params.moments_alpha + lambda, 1.0 / n);
      color = mix(h.color, c, a);
      m = blend_moments(h.moments, l, am);
    } else {
      color = c;
      m = Moments(l, 0.0);
      n = 1.0;
    }
  }
  // Rounded to the nearest half: a store rounding toward zero loses energy every frame (common/color.glsl).
  // Finite and in the fp16 range (samples and histories are clamped): the integer form.
#ifdef COLOR_RGB9E5
  imageStore(integrated, p, uvec4(pack_rgb9e5(color), 0u, 0u, 0u));
#else
  imageStore(integrated, p, round_to_half_clamped(clamp_fp16(vec4(color, m.variance))));
#endif
  const uint seed = uint(p.y) * params.width + uint(p.x) + floatBitsToUint(sample_rgb.g);
  imageStore(moments, p, uvec4(pack_moments(moments_to_stored(m), n, n_rounding(n, seed)), 0u, 0u, 0u));
}
