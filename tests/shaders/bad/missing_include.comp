// Includes a file that does not exist: the tool must name it.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/no_such_file.glsl"
layout(local_size_x = 1) in;
void main() {}
