// gradient_select (A-SVGF forward projection): for each 3x3 stratum of last frame, pick one pixel,
// find where its surface point (same triangle and barycentrics, this frame's vertices) lands now,
// and, if the surface there is the same (depth and normal agree) and nobody claimed that stratum
// yet, give the landing pixel last frame's seed and surface point, and record last frame's
// luminance for the gradient pass. Each stratum is claimed once, so no seed is reused.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/scene_data.glsl"
#include "common/random.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std140) uniform Params {
  Camera camera;
  uint width;
  uint height;
  uint strata_width;
  uint strata_height;
  uint frame;
  uint pad0;
  uint pad1;
  uint pad2;
} params;

layout(set = 0, binding = 3, std430) readonly buffer Triangles { Triangle values[]; } triangles;
layout(set = 0, binding = 10) uniform utexture2D prev_visibility;
layout(set = 0, binding = 11) uniform utexture2D prev_rng_seed;
layout(set = 0, binding = 12) uniform texture2D prev_illumination;
layout(set = 0, binding = 13) uniform texture2D depth_normal;
layout(set = 0, binding = 14, std430) buffer Claims { uint values[]; } claims;
layout(set = 0, binding = 15, rgba32ui) writeonly uniform uimage2D gradient_seeds;
layout(set = 0, binding = 16, rgba32f) writeonly uniform image2D gradient_prev;  // rgba: ESSL 310 has no rg formats

Camera cam;

void main() {
  ivec2 s = ivec2(gl_GlobalInvocationID.xy);
  if (s.x >= int(params.strata_width) || s.y >= int(params.strata_height)) return;
  LOAD_CAMERA(cam, params.camera);
  uint pick = pcg_hash(uint(s.y) * params.strata_width + uint(s.x) + pcg_hash(params.frame)) % 9u;
  ivec2 j = 3 * s + ivec2(int(pick % 3u), int(pick / 3u));
  if (j.x >= int(params.width) || j.y >= int(params.height)) return;
  uvec4 vis = texelFetch(prev_visibility, j, 0);
  if (vis.x == 0u || vis.x == 0xFFFFFFFFu) return;  // nothing, or a light: no shading to compare

  vec3 p0 = triangles.values[vis.y].p0;
  vec3 p1 = triangles.values[vis.y].p1;
  vec3 p2 = triangles.values[vis.y].p2;
  vec2 b = vec2(uintBitsToFloat(vis.z), uintBitsToFloat(vis.w));
  vec3 x = p0 * (1.0 - b.x - b.y) + p1 * b.x + p2 * b.y;
  vec3 c = cross(p1 - p0, p2 - p0);
  float area2 = dot(c, c);
  if (!(area2 > 0.0)) return;  // degenerate now: no normal to test against
  vec3 n = c * inversesqrt(area2);
  if (dot(n, x - cam.position.xyz) > 0.0) n = -n;

  vec3 q3 = camera_project(cam, x, params.width, params.height);
  if (!(q3.z > 0.0)) return;
  ivec2 q = ivec2(floor(q3.xy));
  if (q.x < 0 || q.y < 0 || q.x >= int(params.width) || q.y >= int(params.height)) return;
  vec4 dn = texelFetch(depth_normal, q, 0);
  if (dn.x <= 0.0) return;
  // The same surface: depth within a few pixels' worth of depth gradient, normals aligned.
  float tolerance = max(1e-3 * dn.x, 4.0 * dn.y);
  if (abs(q3.z - dn.x) > tolerance) return;
  if (dot(decode_normal(dn.zw), n) < 0.9) return;

  ivec2 sq = q / 3;
  uint slot = uint(sq.y) * params.strata_width + uint(sq.x);
  if (atomicCompSwap(claims.values[slot], 0u, 1u) != 0u) return;
  uint seed = texelFetch(prev_rng_seed, j, 0).x;
  imageStore(gradient_seeds, q, uvec4(seed, vis.y, vis.z, vis.w));
  float l_prev = luminance(texelFetch(prev_illumination, j, 0).rgb);
  imageStore(gradient_prev, sq, vec4(l_prev, float((q.x % 3) + 3 * (q.y % 3)), 0.0, 0.0));
}
