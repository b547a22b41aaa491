// specular_motion: where the specular signal's history lies last frame (pathtrace's SPLIT_SPECULAR).
// A reflection in a flat mirror shows the reflected point at its virtual image, on the view ray at
// the primary distance plus the reflected ray's length (NRD's "virtual motion"); projecting that
// point with last frame's camera follows the reflection as the camera moves, where the surface's
// motion vector drags it along the floor. Pixels whose first bounce took the diffuse lobe, and
// those without a surface, keep the surface's motion. Exact for static flat reflectors and a moving
// camera; moving reflected objects still need the gradient. z = 1 marks the pixels moved through a
// reflection: only those get the specular temporal pass's looser history test.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/scene_data.glsl"
#include "common/denoise.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std140) uniform Params {
  Camera camera;
  Camera prev_camera;
  uint width;
  uint height;
  uint pad0;  // WGSL rounds a uniform block up to 16 bytes: the C++ struct must be that size
  uint pad1;
} params;

layout(set = 0, binding = 1) uniform utexture2D depth_normal;
#define MOTION_HALVES  // the G-buffer's (gbuffer.comp)
#define MOTION_BINDING 2
#include "common/motion.glsl"
layout(set = 0, binding = 3) uniform texture2D specular;  // a: the first specular ray's length, -1 none hit, 0 no ray
layout(set = 0, binding = 4, rgba32f) writeonly uniform image2D specular_motion;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(params.width) || p.y >= int(params.height)) return;
  Camera cam;
  Camera prev_cam;
  LOAD_CAMERA(cam, params.camera);
  LOAD_CAMERA(prev_cam, params.prev_camera);
  vec4 mv = motion_at(p);
  Surface s = surface_from(texelFetch(depth_normal, p, 0));
  float reflected = texelFetch(specular, p, 0).a;
  if (hit(s) && reflected != 0.0) {
    vec2 centre = vec2(p) + 0.5;
    vec3 d = camera_ray(cam, centre, params.width, params.height);
    vec3 prev_point;
    if (reflected > 0.0) {
      float primary = s.z / max(dot(d, cam.forward.xyz), 1e-6);
      prev_point = cam.position.xyz + d * (primary + reflected);
    } else {
      prev_point = prev_cam.position.xyz + d;  // reflected sky: at infinity, moves with rotation only
    }
    vec3 prev = camera_project(prev_cam, prev_point, params.width, params.height);
    if (prev.z > 0.0) mv = vec4(prev.xy - centre, 1.0, 0.0);
  }
  imageStore(specular_motion, p, mv);
}
