// renderer/gradient_candidate.glsl: A-SVGF's forward projection picks one pixel of each 3x3 stratum
// of last frame and re-shades its sample this frame. pathtrace writes, for each stratum, what the
// projection needs of its picked pixel as it shades it: an image of two RGBA32UI texels a stratum,
// (2 sx, sy) and (2 sx + 1, sy):
//   (seed, triangle, barycentric u, v as float bits)   seed 0: no sample (the pick is off the image,
//                                                      or its ray hit nothing or a light)
//   (luminance as float bits, 0, 0, 0)                 as the gradient compares it (pathtrace.comp)
// so that gradient_select and gradient_resolve read 32 bytes a stratum, not the full-resolution
// visibility (16 bytes a pixel), seed (4) and illumination (8) to use one pixel in nine.
#ifndef ASVGF_RENDERER_GRADIENT_CANDIDATE_GLSL
#define ASVGF_RENDERER_GRADIENT_CANDIDATE_GLSL

#include "common/random.glsl"

// The pixel of stratum s whose sample of frame `frame` the next frame projects (one of its 9, by a
// hash of stratum and frame: chosen by the frame that takes the sample, which cannot know the next
// frame's index); it may lie off the image at its right and bottom edges.
ivec2 gradient_candidate_pixel(uvec2 s, uint strata_width, uint frame) {
  const uint pick = pcg_hash(s.y * strata_width + s.x + pcg_hash(frame)) % 9u;
  return 3 * ivec2(s) + ivec2(int(pick % 3u), int(pick / 3u));
}

ivec2 gradient_candidate_texel(ivec2 s) { return ivec2(2 * s.x, s.y); }
ivec2 gradient_candidate_luminance_texel(ivec2 s) { return ivec2(2 * s.x + 1, s.y); }

#endif
