// gradient_select (A-SVGF forward projection, step 1 of 2): for each 3x3 stratum of last frame,
// find where the surface point of the pixel pathtrace picked (renderer/gradient_candidate.glsl: same
// triangle and barycentrics, this frame's vertices) lands now; if the surface there is the same, bid for the stratum it lands in. The
// lowest bid (last frame's stratum index) wins, whatever order the GPU runs invocations in, so the
// result is reproducible; gradient_resolve then writes for the winners. Each stratum is won once,
// so no seed is reused.
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
layout(set = 0, binding = 14, std430) buffer Claims { uint values[]; } claims;

Camera cam;

#include "renderer/gradient_projection.glsl"

void main() {
  ivec2 s = ivec2(gl_GlobalInvocationID.xy);
  if (s.x >= int(params.strata_width) || s.y >= int(params.strata_height)) return;
  LOAD_CAMERA(cam, params.camera);
  Projection p = project_sample(s);
  if (!p.ok) return;
  ivec2 sq = p.to / 3;
  atomicMin(claims.values[uint(sq.y) * params.strata_width + uint(sq.x)], uint(s.y) * params.strata_width + uint(s.x));
}
