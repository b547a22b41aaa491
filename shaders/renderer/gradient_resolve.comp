// gradient_resolve (A-SVGF forward projection, step 2 of 2): for each stratum of this frame that a
// sample of last frame won in gradient_select, redo that sample's projection (the same function),
// store last frame's seed and surface point for the stratum (gradient_seeds is stratum-sized;
// gradient_prev.y names the landing pixel in it), and record last frame's luminance of the sample
// for the gradient pass: all from the candidate pathtrace wrote (renderer/gradient_candidate.glsl).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/scene_data.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std140) uniform Params {
  Camera camera;
  uint width;
  uint height;
  uint strata_width;
  uint strata_height;
} params;

layout(set = 0, binding = 3, std430) readonly buffer Triangles { Triangle values[]; } triangles;
layout(set = 0, binding = 10) uniform utexture2D gradient_candidates;  // last frame's
layout(set = 0, binding = 13) uniform utexture2D depth_normal;
layout(set = 0, binding = 14, std430) readonly buffer Claims { uint values[]; } claims;
layout(set = 0, binding = 15, rgba32ui) writeonly uniform uimage2D gradient_seeds;
layout(set = 0, binding = 16, rgba32f) writeonly uniform image2D gradient_prev;  // rgba: ESSL 310 has no rg formats

Camera cam;

#include "renderer/gradient_projection.glsl"

void main() {
  ivec2 sq = ivec2(gl_GlobalInvocationID.xy);
  if (sq.x >= int(params.strata_width) || sq.y >= int(params.strata_height)) return;
  LOAD_CAMERA(cam, params.camera);
  uint winner = claims.values[uint(sq.y) * params.strata_width + uint(sq.x)];
  if (winner == 0xFFFFFFFFu) return;  // no sample landed here: gradient_clear's "none" stays
  const ivec2 s = ivec2(int(winner % params.strata_width), int(winner / params.strata_width));
  Projection p = project_sample(s);
  imageStore(gradient_seeds, sq, p.candidate);
  const float l_prev = uintBitsToFloat(texelFetch(gradient_candidates, gradient_candidate_luminance_texel(s), 0).x);
  imageStore(gradient_prev, sq, vec4(l_prev, float((p.to.x % 3) + 3 * (p.to.y % 3)), 0.0, 0.0));
}
