// A GLSL error on line 8: the tool must fail with "glsl_error.comp:8: error: ...".
#version 460
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) writeonly buffer Output { float values[]; } dst;

void main() {
  uint i = gl_GlobalInvocationID.x;
  dst.values[i] = undeclared_value;
}
