// surface.glsl: the one definition of background (no surface at the pixel), for the denoiser's
// passes and the input validator alike, and its CPU twin asvgf::is_background (asvgf/denoiser.hpp):
// a depth that is not finite, not positive or at least kBackgroundDepth (renderers write a huge
// depth for the sky: Cycles 1e10), or a normal that is zero or not finite.
#ifndef ASVGF_SURFACE_GLSL
#define ASVGF_SURFACE_GLSL

#include "common/color.glsl"

const float kBackgroundDepth = 1e9;

bool background_depth(float z) { return not_finite(z) || z <= 0.0 || z >= kBackgroundDepth; }

// The normal's L1 length decides: exactly zero (the background's usual value) or not finite.
bool background_normal(vec3 n) {
  float l1 = abs(n.x) + abs(n.y) + abs(n.z);
  return any_not_finite(n) || !(l1 >= 1e-30) || not_finite(l1);
}

bool is_background(float z, vec3 n) { return background_depth(z) || background_normal(n); }

#endif
