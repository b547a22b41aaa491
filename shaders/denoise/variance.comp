// variance.comp: per-pixel luminance variance for the a-trous filter (SVGF sec. 4.2). With at
// least `min_history` frames of history, the temporal estimate max(0, E[l^2] - E[l]^2); with less,
// a 7x7 edge-aware spatial estimate of the moments (and of the colour), boosted by
// min_history / n as in Falcor's SVGF. Output: rgb colour, a variance (clamped to fp16 max).
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

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  vec3 color = texelFetch(integrated, p, 0).rgb;
  vec3 mn = texelFetch(moments, p, 0).xyz;
  vec2 m = mn.xy;
  float n = mn.z;
  Surface center = surface_from(texelFetch(depth_normal, p, 0));
  float variance = max(0.0, m.y - m.x * m.x);
  if (hit(center) && n > 0.0 && n < params.min_history) {
    float lp = luminance(color);
    vec3 sum_c = vec3(0.0);
    vec2 sum_m = vec2(0.0);
    float sum_w = 0.0;
    for (int dy = -3; dy <= 3; ++dy) {
      for (int dx = -3; dx <= 3; ++dx) {
        ivec2 q = p + ivec2(dx, dy);
        if (q.x < 0 || q.y < 0 || !inside(q, params.width, params.height)) continue;
        float w = 1.0;
        vec3 cq = texelFetch(integrated, q, 0).rgb;
        vec2 mq = m;
        if (dx != 0 || dy != 0) {
          vec3 other_m = texelFetch(moments, q, 0).xyz;
          if (!(other_m.z > 0.0)) continue;
          mq = other_m.xy;
          Surface other = surface_from(texelFetch(depth_normal, q, 0));
          float dist = float(abs(dx) + abs(dy));
          // No variance yet: the luminance weight uses sigma_l alone (std dev taken as 1).
          w = weight_depth(center, other, dist, params.sigma_z) * weight_normal(center, other, params.sigma_n) *
              weight_luminance(lp, luminance(cq), params.sigma_l, 1.0);
        }
        sum_c += w * cq;
        sum_m += w * mq;
        sum_w += w;
      }
    }
    color = sum_c / sum_w;
    m = sum_m / sum_w;
    variance = max(0.0, m.y - m.x * m.x) * (params.min_history / n);
  }
  imageStore(color_variance, p, clamp_fp16(vec4(color, variance)));
}
