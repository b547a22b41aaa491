// local_mean.comp: the local-mean correction (DenoiseSettings::local_mean): scales the filtered
// colour toward the temporal result's local mean of luminance over a window about k pixels wide. The
// a-trous gather, normalised per pixel, loses energy where a bright pixel's neighbours are darker and
// takes local contrast everywhere; the temporal result holds neither loss, and its local mean is far
// less noisy than its pixels (docs/quality.md, "Energy: a correction of the displayed frame's local
// mean"). The scale (common/local_mean.glsl) is shrunk toward 1 where the box mean of the temporal
// result is not known better than its difference from the filtered one's.
// The window is a box of (2 radius + 1)^2 blocks of block x block pixels (local_mean_blocks in
// denoiser/passes/local_mean.hpp: blocks of 1 pixel up to k 15, so that small windows are exact, and
// about 9 blocks a side above), read between the four nearest blocks' boxes bilinearly. Three passes:
// BLOCKS sums each block's three terms (both luminances and the temporal one squared) and pixel
// count (with TEMPORAL_SUMS it takes the temporal terms from another correction's block sums of the
// same blocks and reads the filtered colour only), BOX sums them over each block's window of blocks
// (clamped to the image), the last interpolates and scales. By default the a-trous iterations do the
// first and last passes' work themselves (atrous.comp, LOCAL_MEAN_SUMS and CORRECTS_HISTORY) and the
// composite scales the displayed colour (composite.comp, LOCAL_MEAN): these passes run where they
// cannot (denoiser/passes/denoiser_graph.cpp). Two k-wide separable passes over every pixel cost
// 0.26 ms at 1080p and k 65; the block passes touch each pixel once (docs/quality.md, "The box over
// blocks"). The temporal result is a spatial chain's RGB9E5 words (temporal.comp's COLOR_RGB9E5);
// FILTERED_RGB9E5 (the tapped history's correction) reads `filtered` and writes `corrected` as RGB9E5
// words too, as the colour history is kept.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
#include "common/color.glsl"
#include "common/compute.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;
  uint height;
  int radius;   // in blocks
  uint gated;   // 0: the plain ratio (the tapped history's correction, whose bias would accumulate)
  int block;    // pixels a block's side: 1, 2, 4 or 8
} params;

#ifdef BLOCKS
#ifdef TEMPORAL_SUMS
layout(set = 0, binding = 6) uniform texture2D temporal_sums;  // x, z, w: another correction's block sums
#else
layout(set = 0, binding = 1) uniform utexture2D temporal;  // the temporal pass's result, RGB9E5 words
#endif
#ifdef FILTERED_RGB9E5
layout(set = 0, binding = 2) uniform utexture2D filtered;  // the tapped history, RGB9E5 words
#else
layout(set = 0, binding = 2) uniform texture2D filtered;  // the last a-trous iteration's
#endif
// x: temporal, y: filtered, z: temporal squared (sums), w: pixels
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D block_sums;
#elif defined(BOX)
layout(set = 0, binding = 3) uniform texture2D block_sums;
// x, y, z: the window's means of the three terms
layout(set = 0, binding = 4, rgba32f) writeonly uniform image2D box_means;
#else
#ifdef FILTERED_RGB9E5
layout(set = 0, binding = 2) uniform utexture2D filtered;
layout(set = 0, binding = 5, r32ui) writeonly uniform uimage2D corrected;
#else
layout(set = 0, binding = 2) uniform texture2D filtered;
layout(set = 0, binding = 5, rgba16f) writeonly uniform image2D corrected;
#endif
layout(set = 0, binding = 4) uniform texture2D box_means;
#define LOCAL_MEAN_READS_BOX_MEANS
#endif
#ifdef BLOCKS
#define LOCAL_MEAN_GROUP_X 8
#define LOCAL_MEAN_GROUP_Y 8
#endif
#include "common/local_mean.glsl"

ivec2 size() { return ivec2(params.width, params.height); }
#ifndef BOX
vec3 filtered_color(ivec2 p) {
#ifdef FILTERED_RGB9E5
  return unpack_rgb9e5(texelFetch(filtered, p, 0).x);
#else
  return texelFetch(filtered, p, 0).rgb;
#endif
}
#endif
ivec2 blocks() { return local_mean_blocks(size(), params.block); }

#ifdef BLOCKS
// No return in main: one puts the barrier inside the loop construct that inlining makes of it
// (suspected of stalling NVIDIA's OpenGL SPIR-V path: docs/performance.md).
void main() {
  const ivec2 p = invocation_pixel();
  vec4 t = vec4(0.0);
  if (inside(p, params.width, params.height)) {
#ifdef TEMPORAL_SUMS
    t.y = luminance(filtered_color(p));
#else
    const float lt = luminance(unpack_rgb9e5(texelFetch(temporal, p, 0).x));
    t = vec4(lt, luminance(filtered_color(p)), lt * lt, 1.0);
#endif
  }
  vec4 sum = local_mean_block_sum(t, params.block);
  const ivec2 q = p / params.block;  // this pixel's block
  if (local_mean_block_first(params.block) && all(lessThan(q, blocks()))) {
#ifdef TEMPORAL_SUMS
    const vec4 ts = texelFetch(temporal_sums, q, 0);
    sum = vec4(ts.x, sum.y, ts.zw);
#endif
    imageStore(block_sums, q, sum);
  }
}
#elif defined(BOX)
// Separable within the workgroup: each of its columns' row sums over the window's width, for its 8
// rows and the window's reach above and below, into shared memory; then each texel sums its
// column's 2 radius + 1 row sums. (2 radius + 8)(2 radius + 1) / 8 fetches a texel instead of
// (2 radius + 1)^2: 18 against 81 at 1080p, 51 against 289 at 4K, where the fetches bounded the
// pass (docs/performance.md). Rows and columns outside the blocks' grid add nothing (the window
// clamped to the image).
const int kMaxRadius = 15;  // local_mean_blocks: k <= 255 with blocks of 8
shared vec4 row_sums[(8 + 2 * kMaxRadius) * 8];
// No return in main: the barrier stays at its top level (docs/performance.md).
void main() {
  const ivec2 q = invocation_pixel();
  const ivec2 l = ivec2(gl_LocalInvocationID.xy);
  const ivec2 last = blocks() - 1;
  const int r = params.radius;
  const int first_row = int(gl_WorkGroupID.y) * 8 - r;
  const int lo = max(q.x - r, 0), hi = min(q.x + r, last.x);
  for (int row = l.y; row < 8 + 2 * r; row += 8) {
    const int y = first_row + row;
    vec4 sum = vec4(0.0);
    if (y >= 0 && y <= last.y) {
      // Four fetches issued before their sums (a loop of single fetches waits out each in turn).
      int x = lo;
      for (; x + 3 <= hi; x += 4) {
        const vec4 a = texelFetch(block_sums, ivec2(x, y), 0);
        const vec4 b = texelFetch(block_sums, ivec2(x + 1, y), 0);
        const vec4 c = texelFetch(block_sums, ivec2(x + 2, y), 0);
        const vec4 d = texelFetch(block_sums, ivec2(x + 3, y), 0);
        sum += (a + b) + (c + d);
      }
      for (; x <= hi; ++x) sum += texelFetch(block_sums, ivec2(x, y), 0);
    }
    row_sums[row * 8 + l.x] = sum;
  }
  barrier();
  if (all(lessThanEqual(q, last))) {
    vec4 sum = vec4(0.0);
    for (int dy = 0; dy <= 2 * r; ++dy) sum += row_sums[(l.y + dy) * 8 + l.x];
    imageStore(box_means, q, vec4(sum.xyz / sum.w, 0.0));
  }
}
#else
void main() {
  const ivec2 p = invocation_pixel();
  if (inside(p, params.width, params.height)) {
    const float scale = local_mean_scale(p, size(), params.block, params.radius, params.gated != 0u);
#ifdef FILTERED_RGB9E5
    imageStore(corrected, p, uvec4(local_mean_corrected_rgb9e5(filtered_color(p), scale), 0u, 0u, 0u));
#else
    imageStore(corrected, p, local_mean_corrected(texelFetch(filtered, p, 0), scale));
#endif
  }
}
#endif
