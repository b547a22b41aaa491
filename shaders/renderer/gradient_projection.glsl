// renderer/gradient_projection.glsl: A-SVGF forward projection of one of last frame's samples, shared
// by gradient_select (which claims strata) and gradient_resolve (which writes for the winners), so
// that both compute exactly the same thing.
#ifndef ASVGF_FRAME_GRADIENT_PROJECTION_GLSL
#define ASVGF_FRAME_GRADIENT_PROJECTION_GLSL

#include "renderer/gradient_candidate.glsl"
#include "common/scene_data.glsl"
#include "common/depth_normal.glsl"

// Needs: params (width, height, camera), `triangles` (this frame's), `gradient_candidates` (last
// frame's pathtrace's: renderer/gradient_candidate.glsl), `depth_normal` (this frame's), and a global
// `Camera cam` loaded from params.

struct Projection {
  bool ok;
  ivec2 to;         // this frame's pixel showing the same surface point
  uvec4 candidate;  // last frame's seed, triangle and barycentrics of the stratum's picked pixel
};

// Where last frame's stratum `s`'s candidate sample's surface point (the same triangle and
// barycentrics, this frame's vertices) lands now, if the surface there is the same. Written as
// straight-line code with one exit: naga (the WGSL step) mistranslates early returns out of this once
// inlined.
Projection project_sample(ivec2 s) {
  Projection r;
  const uvec4 candidate = texelFetch(gradient_candidates, gradient_candidate_texel(s), 0);
  // Seed 0: no sample (off the image, or nothing or a light: no shading to compare).
  bool ok = candidate.x != 0u;
  r.candidate = candidate;

  uint tri = ok ? candidate.y : 0u;
  vec3 p0 = triangles.values[tri].p0;
  vec3 p1 = triangles.values[tri].p1;
  vec3 p2 = triangles.values[tri].p2;
  vec2 b = vec2(uintBitsToFloat(candidate.z), uintBitsToFloat(candidate.w));
  vec3 x = p0 * (1.0 - b.x - b.y) + p1 * b.x + p2 * b.y;
  vec3 c = cross(p1 - p0, p2 - p0);
  float area2 = dot(c, c);
  ok = ok && area2 > 0.0;  // degenerate now: no normal to test against
  vec3 n = c * inversesqrt(max(area2, 1e-30));
  n = dot(n, x - cam.position.xyz) > 0.0 ? -n : n;

  vec3 q3 = camera_project(cam, x, params.width, params.height);
  ivec2 q = ivec2(floor(q3.xy));
  ok = ok && q3.z > 0.0 && q.x >= 0 && q.y >= 0 && q.x < int(params.width) && q.y < int(params.height);
  const uvec4 dn = texelFetch(depth_normal, clamp(q, ivec2(0), ivec2(int(params.width) - 1, int(params.height) - 1)), 0);
  const float z = depth_normal_depth(dn);
  // The same surface: depth within a few pixels' worth of depth gradient, normals aligned.
  float tolerance = max(1e-3 * z, 4.0 * depth_normal_gradient(dn));
  ok = ok && z > 0.0 && abs(q3.z - z) <= tolerance && dot(depth_normal_normal(dn), n) >= 0.9;
  r.ok = ok;
  r.to = q;
  return r;
}

#endif
