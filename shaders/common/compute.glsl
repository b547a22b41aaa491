// common/compute.glsl: index helpers shared by compute passes.
#ifndef ASVGF_COMMON_COMPUTE_GLSL
#define ASVGF_COMMON_COMPUTE_GLSL

// The 1D invocation index of a dispatch laid out along x.
uint invocation_index() { return gl_GlobalInvocationID.x; }

// The pixel this invocation covers, and whether it lies inside a width x height image (dispatches
// round the grid up to whole workgroups).
ivec2 invocation_pixel() { return ivec2(gl_GlobalInvocationID.xy); }
bool inside(ivec2 p, uint width, uint height) { return p.x < int(width) && p.y < int(height); }

#endif
