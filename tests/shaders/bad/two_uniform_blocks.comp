// Breaks a portability rule: parameters in two uniform blocks (the HAL fills one).
#version 460
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform A { float a; } pa;
layout(set = 0, binding = 1) uniform B { float b; } pb;
layout(set = 0, binding = 2) writeonly buffer Output { float values[]; } dst;

void main() { dst.values[gl_GlobalInvocationID.x] = pa.a + pb.b; }
