// gbuffer: primary visibility. Per pixel: what the camera ray through the pixel centre hits
// (visibility), its linear depth and screen-space depth gradient, normal, albedo, and the motion
// vector to where the same surface point was last frame.
#version 460
#extension GL_GOOGLE_include_directive : require
#ifdef TRACE_RAY_QUERY
#extension GL_EXT_ray_query : require
#endif
#include "common/scene_data.glsl"
#include "common/depth_normal.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std140) uniform Params {
  Camera camera;
  Camera prev_camera;
  uint width;
  uint height;
  uint sphere_count;
  uint demodulate;  // 0: write albedo 1, the denoiser filters radiance (--no-demodulation); 2: the
                    // diffuse lobe's albedo (pathtrace's SPLIT_SPECULAR writes the GGX lobe's)
} params;

#include "renderer/scene_bindings.glsl"

Camera cam;
Camera prev_cam;

layout(set = 0, binding = 6, std430) readonly buffer PreviousTriangles { Triangle values[]; } previous_triangles;
layout(set = 0, binding = 10, rgba32ui) writeonly uniform uimage2D visibility;
layout(set = 0, binding = 11, rgba16ui) writeonly uniform uimage2D depth_normal;  // common/depth_normal.glsl
// Half floats: 2^-11 of the motion (0.05 px at 100 px) is far below what the bilinear reprojection
// resolves. x and y packed in one word (common/motion.glsl's MOTION_HALVES): ESSL 310 and WebGPU
// store no rg16f, and RGBA16F would move 4 bytes a pixel more here and in the temporal pass.
layout(set = 0, binding = 12, r32ui) writeonly uniform uimage2D motion;
// RGB9E5 words (common/albedo.glsl): what pathtrace.comp divides the radiance by, so exact to
// re-modulate by, in 4 bytes a pixel rather than RGBA16F's 8 (written here, read by the composite and
// the variance estimate).
layout(set = 0, binding = 13, r32ui) writeonly uniform uimage2D albedo;

// View depth where the ray through `pixel` meets the plane (point, normal); 0 if parallel.
float plane_depth(vec2 pixel, vec3 point, vec3 n) {
  vec3 d = camera_ray(cam, pixel, params.width, params.height);
  float denom = dot(n, d);
  float t = dot(n, point - cam.position.xyz) / denom;
  return abs(denom) < 1e-12 ? 0.0 : dot(t * d, cam.forward.xyz);  // one return (common/trace.glsl)
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(params.width) || p.y >= int(params.height)) return;
  LOAD_CAMERA(cam, params.camera);
  LOAD_CAMERA(prev_cam, params.prev_camera);
  vec2 centre = vec2(p) + 0.5;
  vec3 o = cam.position.xyz;
  vec3 d = camera_ray(cam, centre, params.width, params.height);

  Hit h = trace_closest(o, d, 0.0, 1e30, kNoTriangle);
  float t_sphere;
  int sphere = hit_sphere_lights(o, d, 0.0, h.hit ? h.t : 1e30, params.sphere_count, t_sphere);

  uvec4 vis = uvec4(0u);
  uvec4 dn = uvec4(0u);
  vec4 alb = vec4(1.0, 1.0, 1.0, 0.0);
  vec3 prev_point;
  bool at_infinity = false;
  if (sphere >= 0) {
    Light l = load_light(uint(sphere));
    vec3 x = o + t_sphere * d;
    vec3 n = normalize(x - l.position);
    vis = uvec4(0xFFFFFFFFu, uint(sphere), 0u, 0u);
    float z = dot(x - o, cam.forward.xyz);
    float gx = abs(plane_depth(centre + vec2(1.0, 0.0), x, n) - z);
    float gy = abs(plane_depth(centre + vec2(0.0, 1.0), x, n) - z);
    dn = pack_depth_normal(z, max(gx, gy), n);
    alb = vec4(1.0);
    prev_point = x - l.position + l.prev_position;
  } else if (h.hit) {
    Triangle t = load_triangle(h.triangle);
    vec3 x = o + h.t * d;
    vec3 n = normalize(cross(t.p1 - t.p0, t.p2 - t.p0));
    if (dot(n, d) > 0.0) n = -n;
    vis = uvec4(t.instance + 1u, h.triangle, floatBitsToUint(h.bary.x), floatBitsToUint(h.bary.y));
    float z = dot(x - o, cam.forward.xyz);
    float gx = abs(plane_depth(centre + vec2(1.0, 0.0), x, n) - z);
    float gy = abs(plane_depth(centre + vec2(0.0, 1.0), x, n) - z);
    dn = pack_depth_normal(z, max(gx, gy), n);
    if (params.demodulate == 1u) alb = vec4(demodulation_albedo(h.triangle, h.bary, -dot(n, d)), 1.0);
    if (params.demodulate == 2u) {
      vec3 diffuse, specular;
      split_demodulation_albedos(h.triangle, h.bary, -dot(n, d), diffuse, specular);
      alb = vec4(diffuse, 1.0);
    }
    prev_point = previous_triangles.values[h.triangle].p0 * (1.0 - h.bary.x - h.bary.y) +
                 previous_triangles.values[h.triangle].p1 * h.bary.x + previous_triangles.values[h.triangle].p2 * h.bary.y;
  } else {
    // Nothing hit: a point at infinity along d moves only with the camera's rotation.
    at_infinity = true;
    prev_point = prev_cam.position.xyz + d;
  }
  vec3 prev = camera_project(prev_cam, prev_point, params.width, params.height);
  // No previous position (behind last frame's camera): -kFp16Max, far outside any image, as is
  // every motion the clamp shortens (a half float holds no more).
  vec2 mv = prev.z > 0.0 ? clamp(prev.xy - centre, vec2(-kFp16Max), vec2(kFp16Max)) : vec2(-kFp16Max);
  if (at_infinity && prev.z <= 0.0) mv = vec2(-kFp16Max);

  imageStore(visibility, p, vis);
  imageStore(depth_normal, p, dn);
  // Rounded to the nearest half: packHalf2x16's rounding, like a store's, is the implementation's,
  // and rounding toward zero would shorten every motion (common/color.glsl).
  imageStore(motion, p, uvec4(packHalf2x16(round_to_half_clamped(vec4(mv, 0.0, 0.0)).xy)));
  imageStore(albedo, p, uvec4(pack_rgb9e5(alb.rgb)));
}
