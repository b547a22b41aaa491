// variance.comp: per-pixel luminance variance for the a-trous filter (SVGF sec. 4.2). With at
// least `min_history` frames of history, the temporal estimate max(0, E[l^2] - E[l]^2); with less,
// a 7x7 edge-aware spatial estimate of the moments (and of the colour), boosted by
// min_history / n as in Falcor's SVGF, except that with one frame of history the moments are
// weighted by depth and normal only (see below). Output: rgb colour, a variance (clamped to fp16 max).
// The 7x7 neighbours are fetched directly, only by pixels with a short history: a shared-memory
// tile of them, loaded by any workgroup with one such pixel, cost its barriers and shared memory
// in every workgroup: it lost more on frames with long histories than it saved where every pixel
// needs the estimate (docs/performance.md).
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
layout(set = 0, binding = 1) uniform texture2D integrated;
layout(set = 0, binding = 2) uniform texture2D moments;  // E[l], E[l^2], history length
layout(set = 0, binding = 3) uniform texture2D depth_normal;
layout(set = 0, binding = 4, rgba16f) writeonly uniform image2D color_variance;

const int kRadius = 3;

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  vec3 color = texelFetch(integrated, p, 0).rgb;
  vec3 mn = texelFetch(moments, p, 0).xyz;
  Surface center = surface_from(texelFetch(depth_normal, p, 0));
  vec2 m = mn.xy;
  float n = mn.z;
  float variance = max(0.0, m.y - m.x * m.x);

  if (hit(center) && n > 0.0 && n < params.min_history) {
    float lp = luminance(color);
    vec3 sum_c = vec3(0.0);
    vec2 sum_m = vec2(0.0);
    float sum_w = 0.0, sum_wm = 0.0;
    for (int dy = -kRadius; dy <= kRadius; ++dy) {
      for (int dx = -kRadius; dx <= kRadius; ++dx) {
        float w = 1.0, w_surface = 1.0;
        vec3 cq = color;
        vec2 mq = m;
        if (dx != 0 || dy != 0) {
          ivec2 q = p + ivec2(dx, dy);
          if (q.x < 0 || q.y < 0 || !inside(q, params.width, params.height)) continue;
          vec3 other_m = texelFetch(moments, q, 0).xyz;
          if (!(other_m.z > 0.0)) continue;  // a neighbour without history is not part of the estimate
          mq = other_m.xy;
          cq = texelFetch(integrated, q, 0).rgb;
          Surface other = surface_from(texelFetch(depth_normal, q, 0));
          float dist = float(abs(dx) + abs(dy));
          w_surface = weight_depth(center, other, dist, params.sigma_z) * weight_normal(center, other, params.sigma_n);
          // No variance yet: the luminance weight uses sigma_l alone (std dev taken as 1).
          w = w_surface * weight_luminance(lp, luminance(cq), params.sigma_l, 1.0);
        }
        sum_c += w * cq;
        sum_w += w;
        // One frame of history: a pixel's own moments hold no variance (E[l^2] = E[l]^2), so the
        // estimate is the spread of its neighbours' luminance, which the luminance weight would
        // cut exactly where it is large: a firefly (l >> sigma_l) would get variance 0 and survive
        // the a-trous untouched (glossy first frame: relMSE 0.30 against 0.028 at 192x192).
        float wm = n < 1.5 ? w_surface : w;
        sum_m += wm * mq;
        sum_wm += wm;
      }
    }
    color = sum_c / sum_w;
    m = sum_m / sum_wm;
    variance = max(0.0, m.y - m.x * m.x) * (params.min_history / n);
  }
  imageStore(color_variance, p, clamp_fp16(vec4(color, variance)));
}
