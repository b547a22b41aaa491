// common/local_mean.glsl: the local-mean correction's scale at one pixel (DenoiseSettings::local_mean;
// denoise/local_mean.comp computes the windows' means), for local_mean.comp's apply pass and for the
// composite pass that applies the displayed colour's correction itself (composite.comp, LOCAL_MEAN).
// The scale's functions need the texture `box_means` (xyz: a window's means of the temporal
// luminance, the filtered luminance and the temporal luminance squared, one texel a block): an
// including shader that declares it defines LOCAL_MEAN_READS_BOX_MEANS.
#ifndef ASVGF_COMMON_LOCAL_MEAN_GLSL
#define ASVGF_COMMON_LOCAL_MEAN_GLSL

// The blocks' grid of a size x size image (partial blocks at the right and bottom edges).
ivec2 local_mean_blocks(ivec2 size, int block) { return (size + block - 1) / block; }

#ifdef LOCAL_MEAN_GROUP_X
// The block sums of a workgroup of LOCAL_MEAN_GROUP_X x LOCAL_MEAN_GROUP_Y invocations (the includer
// defines both; blocks of `block` pixels, a power of two dividing both, so that no block crosses
// workgroups): each block row summed by its first invocation, then the rows by the block's first:
// 2 x block adds in series, not block^2, unrolled to the largest block so that a row's loads issue
// together (0.004 ms less in the first iteration at 1080p on an H100: docs/performance.md, "The local
// mean's cost, measured"). Every invocation of the workgroup calls it (barriers); the result is the
// block's sum where the invocation is its block's first (local_mean_block_first). The includer
// enables GL_EXT_control_flow_attributes.
const int kLocalMeanMaxBlock = 8;  // DenoiseSettings: blocks of 1, 2, 4 or 8 pixels
// The terms summed: vec4, or float where the includer sums one (LOCAL_MEAN_SUM_TYPE), in a quarter
// of the shared memory. The includer may instead give two shared arrays of that type and at least a
// workgroup's entries to reuse (LOCAL_MEAN_TERMS, LOCAL_MEAN_ROWS): they are overwritten after a
// barrier.
#ifndef LOCAL_MEAN_SUM_TYPE
#define LOCAL_MEAN_SUM_TYPE vec4
#endif
#ifdef LOCAL_MEAN_TERMS
#define local_mean_terms LOCAL_MEAN_TERMS
#define local_mean_rows LOCAL_MEAN_ROWS
#else
shared LOCAL_MEAN_SUM_TYPE local_mean_terms[LOCAL_MEAN_GROUP_X * LOCAL_MEAN_GROUP_Y];
shared LOCAL_MEAN_SUM_TYPE local_mean_rows[LOCAL_MEAN_GROUP_X * LOCAL_MEAN_GROUP_Y];
#endif
bool local_mean_block_first(int block) {
  const ivec2 l = ivec2(gl_LocalInvocationID.xy);
  return l.x % block == 0 && l.y % block == 0;
}
LOCAL_MEAN_SUM_TYPE local_mean_block_sum(LOCAL_MEAN_SUM_TYPE terms, int block) {
  const ivec2 l = ivec2(gl_LocalInvocationID.xy);
#ifdef LOCAL_MEAN_TERMS
  barrier();  // every invocation done with what the arrays held
#endif
  local_mean_terms[l.y * LOCAL_MEAN_GROUP_X + l.x] = terms;
  barrier();
  if (l.x % block == 0) {
    LOCAL_MEAN_SUM_TYPE sum = LOCAL_MEAN_SUM_TYPE(0.0);
    [[unroll]] for (int x = 0; x < kLocalMeanMaxBlock; ++x)
      if (x < block) sum += local_mean_terms[l.y * LOCAL_MEAN_GROUP_X + l.x + x];
    local_mean_rows[l.y * LOCAL_MEAN_GROUP_X + l.x] = sum;
  }
  barrier();
  LOCAL_MEAN_SUM_TYPE sum = LOCAL_MEAN_SUM_TYPE(0.0);
  if (local_mean_block_first(block))
    [[unroll]] for (int y = 0; y < kLocalMeanMaxBlock; ++y)
      if (y < block) sum += local_mean_rows[(l.y + y) * LOCAL_MEAN_GROUP_X + l.x];
  return sum;
}
#endif

#ifdef LOCAL_MEAN_READS_BOX_MEANS

// The window's means at p: the four nearest blocks' boxes, bilinearly (block centres at
// (i + 0.5) block), clamped to the blocks' grid. With blocks of 1 pixel, p's own box exactly.
vec3 local_mean_window(ivec2 p, ivec2 size, int block) {
  const vec2 last = vec2(local_mean_blocks(size, block) - 1);
  const vec2 u = clamp((vec2(p) + 0.5) / float(block) - 0.5, vec2(0.0), last);
  const ivec2 i0 = ivec2(floor(u));
  const ivec2 i1 = min(i0 + 1, ivec2(last));
  const vec2 f = u - vec2(i0);
  const vec3 top = mix(texelFetch(box_means, i0, 0).xyz, texelFetch(box_means, ivec2(i1.x, i0.y), 0).xyz, f.x);
  const vec3 bottom = mix(texelFetch(box_means, ivec2(i0.x, i1.y), 0).xyz, texelFetch(box_means, i1, 0).xyz, f.x);
  return mix(top, bottom, f.y);
}

// The scale of p's filtered colour: 1 + g (ratio - 1), the ratio of the window's temporal mean to
// its filtered mean, g = d^2 / (d^2 + se^2) with `gated` (d the means' difference, se^2 the window's
// spatial variance of the temporal luminance over its pixel count), else 1.
float local_mean_scale(ivec2 p, ivec2 size, int block, int radius, bool gated) {
  const vec3 mean = local_mean_window(p, size, block);
  const float d2 = (mean.x - mean.y) * (mean.x - mean.y);
  const float window = float((2 * radius + 1) * block);  // the window's side in pixels
  const float se2 = max(mean.z - mean.x * mean.x, 0.0) / (window * window);
  const float g = !gated ? 1.0 : d2 + se2 > 0.0 ? d2 / (d2 + se2) : 0.0;
  // Nothing filtered to scale (a black neighbourhood): left as it is.
  return mean.y > 1e-6 ? 1.0 + g * (mean.x / mean.y - 1.0) : 1.0;
}

// The corrected colour as the apply pass stores it (RGBA16F), so that the composite's own
// correction displays exactly what the apply pass's image holds.
vec4 local_mean_corrected(vec4 filtered, float scale) {
  return round_to_half(clamp_fp16(vec4(filtered.rgb * scale, filtered.a)));
}
// The corrected colour history as RGB9E5 words (common/color.glsl), as the apply pass's
// FILTERED_RGB9E5 variant and the a-trous iteration that corrects the history both store it.
uint local_mean_corrected_rgb9e5(vec3 filtered, float scale) { return pack_rgb9e5(filtered * scale); }
#endif

#endif
