// variance.comp: per-pixel luminance variance for the a-trous filter (SVGF sec. 4.2). With at
// least `min_history` frames of history, the temporal estimate max(0, E[l^2] - E[l]^2); with less,
// a 7x7 edge-aware spatial estimate of the moments (and of the colour), boosted by
// min_history / n as in Falcor's SVGF, except that with one frame of history the moments are
// weighted by depth and normal only (see below). Output: rgb colour, a variance (clamped to fp16 max).
// The dispatch must use whole 8x8 workgroups (the tile is addressed by workgroup id).
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

// The 7x7 spatial estimate reads each neighbour's colour, moments and surface 49 times over a
// workgroup: they are loaded once per workgroup into shared memory (an 8x8 group's 14x14 tile),
// and only by groups where some pixel has a short history.
const int kRadius = 3;
const int kTile = 8 + 2 * kRadius;
shared vec4 tile_color[kTile * kTile];    // rgb, luminance
shared vec4 tile_moments[kTile * kTile];  // E[l], E[l^2], history length (0: outside the image)
shared vec4 tile_surface[kTile * kTile];  // depth (0: no hit), normal
shared uint group_needs_tile;

void main() {
  ivec2 p = invocation_pixel();
  bool in_image = inside(p, params.width, params.height);
  vec3 color = vec3(0.0);
  vec3 mn = vec3(0.0);
  Surface center = Surface(0.0, 0.0, vec3(0.0));
  if (in_image) {
    color = texelFetch(integrated, p, 0).rgb;
    mn = texelFetch(moments, p, 0).xyz;
    center = surface_from(texelFetch(depth_normal, p, 0));
  }
  vec2 m = mn.xy;
  float n = mn.z;
  float variance = max(0.0, m.y - m.x * m.x);
  bool spatial = in_image && hit(center) && n > 0.0 && n < params.min_history;

  if (gl_LocalInvocationIndex == 0u) group_needs_tile = 0u;
  barrier();
  if (spatial) atomicOr(group_needs_tile, 1u);
  barrier();
  // The same for the whole group; the barrier after it stays outside (WGSL's uniformity analysis
  // cannot know that a shared value is uniform).
  if (group_needs_tile != 0u) {
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * 8 - kRadius;
    for (uint i = gl_LocalInvocationIndex; i < uint(kTile * kTile); i += 64u) {
      ivec2 q = origin + ivec2(int(i) % kTile, int(i) / kTile);
      vec4 c = vec4(0.0), mq = vec4(0.0), sq = vec4(0.0);
      if (q.x >= 0 && q.y >= 0 && inside(q, params.width, params.height)) {
        c.rgb = texelFetch(integrated, q, 0).rgb;
        c.a = luminance(c.rgb);
        mq.xyz = texelFetch(moments, q, 0).xyz;
        Surface s = surface_from(texelFetch(depth_normal, q, 0));
        sq = vec4(s.z, s.n);
      }
      tile_color[i] = c;
      tile_moments[i] = mq;
      tile_surface[i] = sq;
    }
  }
  barrier();

  if (spatial) {
    float lp = luminance(color);
    vec3 sum_c = vec3(0.0);
    vec2 sum_m = vec2(0.0);
    float sum_w = 0.0, sum_wm = 0.0;
    ivec2 local = ivec2(gl_LocalInvocationID.xy) + kRadius;
    for (int dy = -kRadius; dy <= kRadius; ++dy) {
      for (int dx = -kRadius; dx <= kRadius; ++dx) {
        int t = (local.y + dy) * kTile + local.x + dx;
        vec4 other_m = tile_moments[t];
        // Outside the image, or (a neighbour) without history: not part of the estimate.
        if (!(other_m.z > 0.0) && (dx != 0 || dy != 0)) continue;
        float w = 1.0, w_surface = 1.0;
        vec4 cq = tile_color[t];
        vec2 mq = m;
        if (dx != 0 || dy != 0) {
          mq = other_m.xy;
          vec4 sq = tile_surface[t];
          Surface other = Surface(sq.x, 0.0, sq.yzw);  // a neighbour's depth gradient is never used
          float dist = float(abs(dx) + abs(dy));
          w_surface = weight_depth(center, other, dist, params.sigma_z) * weight_normal(center, other, params.sigma_n);
          // No variance yet: the luminance weight uses sigma_l alone (std dev taken as 1).
          w = w_surface * weight_luminance(lp, cq.a, params.sigma_l, 1.0);
        }
        sum_c += w * cq.rgb;
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
  if (in_image) imageStore(color_variance, p, clamp_fp16(vec4(color, variance)));
}
