// debug_view: one intermediate buffer as a displayable image (the demo's buffer views).
// mode 0 normals, 1 linear depth, 2 motion, 3 albedo, 4 noisy input (tonemapped), and the denoiser's
// state as heat maps (black, red, yellow, white): 5 temporal gradient lambda = min(1, antilag |delta^|/Delta^),
// 6 temporal blend factor alpha = max((1 - lambda) alpha + lambda, 1/n) as the temporal pass computes
// it, 7 standard deviation of luminance s/(1+s) (what the a-trous filter is steered by),
// 8 history length n / history_cap. A buffer the method does not have (`available` bit clear)
// shows black.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#include "common/denoise.glsl"
#include "common/scene_data.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std140) uniform Params {
  uint width;
  uint height;
  uint mode;
  float depth_scale;  // depth shown as depth * depth_scale
  float alpha;        // the temporal pass's constant alpha
  float history_cap;
  uint available;     // 1: gradient (1/3 res: delta^, Delta^), 2: moments (E[l], sqrt(Var[l]), n), 4: variance (.a)
  float antilag;      // the temporal pass's gradient response (DenoiseSettings::antilag)
} params;

layout(set = 0, binding = 1) uniform utexture2D depth_normal;
#define MOTION_HALVES  // the G-buffer's (gbuffer.comp)
#define MOTION_BINDING 2
#include "common/motion.glsl"
#define ALBEDO_RGB9E5  // the G-buffer's (gbuffer.comp)
#define ALBEDO_BINDING 3
#include "common/albedo.glsl"
layout(set = 0, binding = 4) uniform texture2D illumination;
layout(set = 0, binding = 5, rgba8) writeonly uniform image2D debug_view;
layout(set = 0, binding = 6) uniform texture2D gradient;
layout(set = 0, binding = 7) uniform utexture2D moments;  // common/denoise.glsl: pack_moments
layout(set = 0, binding = 8) uniform texture2D variance;

vec3 heat(float t) {
  t = clamp(t, 0.0, 1.0);
  return clamp(vec3(3.0 * t, 3.0 * t - 1.0, 3.0 * t - 2.0), 0.0, 1.0);
}

float gradient_lambda(ivec2 p) {
  if ((params.available & 1u) == 0u) return 0.0;
  return gradient_response(texelFetch(gradient, min(p / 3, textureSize(gradient, 0) - 1), 0).xy, params.antilag);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(params.width) || p.y >= int(params.height)) return;
  const uvec4 dn = texelFetch(depth_normal, p, 0);
  const float z = depth_normal_depth(dn);
  vec3 c = vec3(0.0);
  if (params.mode == 0u) {
    c = z > 0.0 ? depth_normal_normal(dn) * 0.5 + 0.5 : vec3(0.0);
  } else if (params.mode == 1u) {
    c = vec3(clamp(z * params.depth_scale, 0.0, 1.0));
  } else if (params.mode == 2u) {
    vec2 m = motion_at(p).xy;
    c = abs(m.x) > 1e5 ? vec3(1.0, 0.0, 1.0) : vec3(clamp(0.5 + m * 0.05, 0.0, 1.0), 0.5);
  } else if (params.mode == 3u) {
    c = albedo_at(p);
  } else if (params.mode == 4u) {
    vec3 l = texelFetch(illumination, p, 0).rgb * albedo_at(p);
    c = l / (1.0 + l);
  } else if (params.mode == 5u) {
    c = heat(gradient_lambda(p));
  } else if (params.mode == 6u) {
    if ((params.available & 2u) != 0u) {
      float n = unpack_moments(texelFetch(moments, p, 0).x).z;
      float lambda = gradient_lambda(p);
      c = heat(n > 0.0 ? max((1.0 - lambda) * params.alpha + lambda, 1.0 / n) : 1.0);
    }
  } else if (params.mode == 7u) {
    if ((params.available & 4u) != 0u) {
      float s = sqrt(max(texelFetch(variance, p, 0).a, 0.0));
      c = heat(s / (1.0 + s));
    }
  } else {
    if ((params.available & 2u) != 0u) c = heat(unpack_moments(texelFetch(moments, p, 0).x).z / max(params.history_cap, 1.0));
  }
  imageStore(debug_view, p, vec4(c, 1.0));
}
