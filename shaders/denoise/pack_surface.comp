// pack_surface.comp: the renderer's linear depth and world-space normal as the denoiser's
// depth_normal texel (common/depth_normal.glsl: depth, depth gradient, octahedral normal). A background pixel
// (common/surface.glsl: no finite depth in (0, 1e9), or a zero normal) is all zero: no filter weight
// reaches it and no history is reprojected onto it. The depth gradient is the
// renderer's (depth.y) when given, else estimated from the neighbours: per axis the smaller
// difference to a neighbour that is not background (the one on the same surface at a silhouette),
// then the larger of the two axes, as the G-buffer's max(|dz/dx|, |dz/dy|).
// CPU twin: reference::pack_surface (pipeline/cpu_oracle/denoise_reference.cpp).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/color.glsl"
#include "common/compute.glsl"
#include "common/depth_normal.glsl"
#include "common/surface.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  uint depth_gradient_given;  // 1: depth.y holds max(|dz/dx|, |dz/dy|)
  uint pad;
} params;
layout(set = 0, binding = 1) uniform texture2D depth;   // x: linear view depth; y: its gradient (optional)
layout(set = 0, binding = 2) uniform texture2D normal;  // xyz: world-space normal
layout(set = 0, binding = 3, rgba16ui) writeonly uniform uimage2D depth_normal;

// The depth at q, or 0 outside the image and on background.
float depth_at(ivec2 q) {
  if (q.x < 0 || q.y < 0 || !inside(q, params.width, params.height)) return 0.0;
  float z = texelFetch(depth, q, 0).x;
  return background_depth(z) ? 0.0 : z;
}

// The smaller |z_q - z| over the two neighbours along `axis` that are not background; 0 if neither.
float axis_gradient(ivec2 p, float z, ivec2 axis) {
  float a = depth_at(p - axis), b = depth_at(p + axis);
  float g = 3.4e38;
  if (a > 0.0) g = abs(a - z);
  if (b > 0.0) g = min(g, abs(b - z));
  return g == 3.4e38 ? 0.0 : g;
}

void main() {
  ivec2 p = invocation_pixel();
  if (!inside(p, params.width, params.height)) return;
  vec2 zg = texelFetch(depth, p, 0).xy;
  vec3 n = texelFetch(normal, p, 0).xyz;
  uvec4 texel = uvec4(0u);
  if (!is_background(zg.x, n)) {
    float dz = zg.y;
    if (params.depth_gradient_given == 0u || not_finite(dz) || dz < 0.0)
      dz = max(axis_gradient(p, zg.x, ivec2(1, 0)), axis_gradient(p, zg.x, ivec2(0, 1)));
    texel = pack_depth_normal(zg.x, dz, n);
  }
  imageStore(depth_normal, p, texel);
}
