// debug_view: one intermediate buffer as a displayable image (the demo's buffer views).
// mode 0 normals, 1 linear depth, 2 motion, 3 albedo, 4 noisy input (tonemapped).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/scene_data.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std140) uniform Params {
  uint width;
  uint height;
  uint mode;
  float depth_scale;  // depth shown as depth * depth_scale
} params;

layout(set = 0, binding = 1) uniform texture2D depth_normal;
layout(set = 0, binding = 2) uniform texture2D motion;
layout(set = 0, binding = 3) uniform texture2D albedo;
layout(set = 0, binding = 4) uniform texture2D illumination;
layout(set = 0, binding = 5, rgba8) writeonly uniform image2D debug_view;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(params.width) || p.y >= int(params.height)) return;
  vec4 dn = texelFetch(depth_normal, p, 0);
  vec3 c = vec3(0.0);
  if (params.mode == 0u) {
    c = dn.x > 0.0 ? decode_normal(dn.zw) * 0.5 + 0.5 : vec3(0.0);
  } else if (params.mode == 1u) {
    c = vec3(clamp(dn.x * params.depth_scale, 0.0, 1.0));
  } else if (params.mode == 2u) {
    vec2 m = texelFetch(motion, p, 0).xy;
    c = abs(m.x) > 1e5 ? vec3(1.0, 0.0, 1.0) : vec3(clamp(0.5 + m * 0.05, 0.0, 1.0), 0.5);
  } else if (params.mode == 3u) {
    c = texelFetch(albedo, p, 0).rgb;
  } else {
    vec3 l = texelFetch(illumination, p, 0).rgb * texelFetch(albedo, p, 0).rgb;
    c = l / (1.0 + l);
  }
  imageStore(debug_view, p, vec4(c, 1.0));
}
