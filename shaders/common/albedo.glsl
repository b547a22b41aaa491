// common/albedo.glsl: the albedo a pass re-modulates by, in either format the denoiser takes (the
// including shader defines ALBEDO_BINDING first):
//   a float texture (rgb), e.g. the caller's RGBA16F or RGBA32F;
//   with ALBEDO_RGB9E5, an R32UI image of RGB9E5 words (common/color.glsl): 4 bytes a pixel where
//   RGBA16F takes 8. RGB9E5 gives every channel the largest one's step (2^-9 to 2^-8 of it), so a
//   dark channel beside a bright one rounds by much of itself (1/32 at 1/16 of the largest, to 0
//   below about 1/512): it is for renderers that divided their radiance by the word's own value;
//   then re-modulating gives back the radiance they divided, as with any albedo. Our path tracer
//   (the G-buffer's word) and the denoiser's own demodulation (convert_inputs.comp) do.
#ifndef ASVGF_COMMON_ALBEDO_GLSL
#define ASVGF_COMMON_ALBEDO_GLSL

#include "common/color.glsl"

#ifdef ALBEDO_RGB9E5
layout(set = 0, binding = ALBEDO_BINDING) uniform utexture2D albedo;
vec3 albedo_at(ivec2 p) { return unpack_rgb9e5(texelFetch(albedo, p, 0).x); }
#else
layout(set = 0, binding = ALBEDO_BINDING) uniform texture2D albedo;
vec3 albedo_at(ivec2 p) { return texelFetch(albedo, p, 0).rgb; }
#endif

#endif
