// common/motion.glsl: a pixel's motion (previous minus current position, in pixels), in either
// format the denoiser takes (the including shader defines MOTION_BINDING first):
//   a float texture (xy; z: specular_motion.comp's virtual-motion flag, where it is given);
//   with MOTION_HALVES, an R32UI image of x and y as packHalf2x16's halves: 4 bytes a pixel where
//   RGBA16F takes 8 (GLES and WebGPU store no rg16f), the same halves.
#ifndef ASVGF_COMMON_MOTION_GLSL
#define ASVGF_COMMON_MOTION_GLSL

#ifdef MOTION_HALVES
layout(set = 0, binding = MOTION_BINDING) uniform utexture2D motion;
vec4 motion_at(ivec2 p) { return vec4(unpackHalf2x16(texelFetch(motion, p, 0).x), 0.0, 0.0); }
#else
layout(set = 0, binding = MOTION_BINDING) uniform texture2D motion;
vec4 motion_at(ivec2 p) { return texelFetch(motion, p, 0); }
#endif

#endif
