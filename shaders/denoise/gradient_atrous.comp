// gradient_atrous.comp: one edge-aware a-trous iteration over the sparse gradient (delta, Delta)
// at 1/3 resolution (A-SVGF sec. 5.2), dispatched k times with step 2^i. Each stratum is guided by
// its centre pixel's depth and normal; 3x3 binomial kernel. No luminance weight: the gradient
// itself is what is being reconstructed.
// The guide is depth_normal at each stratum's centre pixel: 1 texel in 9. Variants: GUIDE_OUT (the
// first of several iterations) also writes those texels into a 1/3-resolution image; GUIDE_IN (the
// later ones) reads them there instead of depth_normal (whose every iteration counted 8 bytes a
// pixel against the strata's 0.9). SAMPLES_IN (the first iteration, where the renderer gives l_cur)
// reads the gradient samples (l_prev, index, l_cur) and computes (delta, Delta) itself, once a
// stratum into a shared tile (common/gradient_sample.glsl), bit for bit what the gradient pass would
// have stored, so that pass and its image do not run.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : require
#include "common/compute.glsl"
#include "common/denoise.glsl"
#include "common/gradient_sample.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Params {
  uint width;  // full resolution (of depth_normal)
  uint height;
  uint gradient_width;
  uint gradient_height;
  int step;  // 2^iteration, in strata
  float sigma_z;
  float sigma_n;
  uint luminance_in_alpha;  // SAMPLES_IN: the samples' l_prev < 0 means missing (split signals)
} params;
// (delta, Delta); with SAMPLES_IN the gradient samples (l_prev, index or -1, l_cur, -).
layout(set = 0, binding = 1) uniform texture2D gradient_in;
#ifdef GUIDE_IN
layout(set = 0, binding = 2) uniform utexture2D strata_guide;
#else
layout(set = 0, binding = 2) uniform utexture2D depth_normal;
#endif
layout(set = 0, binding = 3, rgba16f) writeonly uniform image2D gradient_out;
#ifdef GUIDE_OUT
layout(set = 0, binding = 4, rgba16ui) writeonly uniform uimage2D strata_guide_out;
#endif

ivec2 guide_pixel(ivec2 s) { return min(3 * s + 1, ivec2(params.width, params.height) - 1); }

// depth_normal's texel at stratum s's centre pixel.
uvec4 guide_texel(ivec2 s) {
#ifdef GUIDE_IN
  return texelFetch(strata_guide, s, 0);
#else
  return texelFetch(depth_normal, guide_pixel(s), 0);
#endif
}

#ifdef SAMPLES_IN
// Step 1 only: the workgroup's 8x8 strata and their taps lie in one 10x10 block, whose gradients are
// computed once each into shared memory (each tap computing its own, 9 a stratum, cost the pass
// 0.007 ms at 1080p on an H100: docs/performance.md).
const int kTile = 10;
shared vec2 tile_gradient[kTile * kTile];
ivec2 tile_origin() { return ivec2(gl_WorkGroupID.xy) * 8 - 1; }
void load_tile() {
  const ivec2 grid = ivec2(params.gradient_width, params.gradient_height);
  for (int k = int(gl_LocalInvocationIndex); k < kTile * kTile; k += 64) {
    const ivec2 q = tile_origin() + ivec2(k % kTile, k / kTile);
    const bool in_grid = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, grid));
    const vec4 sample_q = texelFetch(gradient_in, clamp(q, ivec2(0), grid - 1), 0);
    tile_gradient[k] = in_grid ? gradient_of_given_sample(q, sample_q, params.width, params.height,
                                                          params.luminance_in_alpha != 0u)
                               : vec2(0.0);
  }
}
vec2 tap_gradient(ivec2 q) {
  const ivec2 t = q - tile_origin();
  return tile_gradient[t.y * kTile + t.x];
}
#else
vec2 tap_gradient(ivec2 q) { return texelFetch(gradient_in, q, 0).xy; }
#endif

void filter_stratum(ivec2 s) {
  ivec2 gp = guide_pixel(s);
  const uvec4 center_texel = guide_texel(s);
#ifdef GUIDE_OUT
  imageStore(strata_guide_out, s, center_texel);
#endif
  Surface center = surface_from(center_texel);
  vec2 sum = vec2(0.0);
  float weights = 0.0;
  // Unrolled, no `continue` (spirv-opt unrolls only loops without one): see atrous.comp.
  [[unroll]] for (int dy = -1; dy <= 1; ++dy) {
    [[unroll]] for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = s + params.step * ivec2(dx, dy);
      if (inside(q, params.gradient_width, params.gradient_height) && all(greaterThanEqual(q, ivec2(0)))) {
        const vec2 g = tap_gradient(q);
        float w = binomial3(dx) * binomial3(dy);
        if (dx != 0 || dy != 0) {
          ivec2 gq = guide_pixel(q);
          if (hit(center)) {
            Surface other = surface_from(guide_texel(q));
            float dist = float(abs(gq.x - gp.x) + abs(gq.y - gp.y));
            w *= weight_depth(center, other, dist, params.sigma_z) * weight_normal(center, other, params.sigma_n);
          }
        }
        sum += w * g;
        weights += w;
      }
    }
  }
  imageStore(gradient_out, s, vec4(round_to_half(sum / weights), 0.0, 0.0));
}

// No return before the tile's barrier (every invocation reaches it).
void main() {
#ifdef SAMPLES_IN
  load_tile();
  barrier();
#endif
  ivec2 s = invocation_pixel();
  if (inside(s, params.gradient_width, params.gradient_height)) filter_stratum(s);
}
