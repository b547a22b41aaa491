// The GLSL error is in the included file: the message must name broken_include.glsl, line 5.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "broken_include.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) writeonly buffer Output { float values[]; } dst;

void main() { dst.values[gl_GlobalInvocationID.x] = broken(); }
