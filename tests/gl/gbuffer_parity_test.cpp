// The G-buffer and the path-traced illumination on OpenGL 4.5 and OpenGL ES 3.1 against Vulkan's
// software-BVH variant. The shaders are the same, but Vulkan compiles the SPIR-V and GL compiles
// SPIRV-Cross's GLSL: the two front ends order and fuse arithmetic that is not `precise` (the
// camera ray, t = depth / det, shading) differently, so 40-55% of the pixels differ in their last
// bits (measured on llvmpipe, 48x40: depth 4.1e-6 relative, normal 3.0e-5, barycentrics 1.2e-6,
// motion 1.1e-5 px, illumination 2.2e-5 relative at worst; one shared-edge tie in static on GL). Motion
// and illumination are stored as half floats, so such a last-bit difference can also round them to
// neighbouring halves (one half step: 2^-10 of the value at most). Every difference must be one of
// two kinds:
//  - the same surface hit, every value within a few hundred float ulps of its magnitude (one half
//    step for the half-float images);
//  - a different triangle, where the pixel's ray passes through an edge both triangles share
//    (both hits on an edge): the nearer-or-lower-index tie-break then depends on t's last bit.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "gl/gl_device.hpp"
#include "pipeline/frame_inputs.hpp"
#include "renderer/scene/builtin.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;

namespace {

// Bounds for "the same surface": an order of magnitude above what was measured, far below what a
// wrong hit point, normal or bounce would give; for the half-float motion and illumination, one
// half step (2^-10 relative at most) above that, and for the depth gradient and normal one step of
// their encodings (shaders/common/depth_normal.glsl).
constexpr double kDepthRelative = 1e-4, kNormalAbsolute = 1e-4, kBaryAbsolute = 1e-5, kMotionPixels = 1e-4,
                 kIlluminationRelative = 1e-4, kHalfStep = 0x1p-10, kGradientStep = 0x1p-8,
                 kOctahedralStep = 1.0 / 2047;
constexpr float kOnEdge = 1e-5f;  // smallest barycentric weight of a hit on an edge

float as_float(std::uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

struct Explained {
  int identical = 0, rounding = 0, shared_edge = 0, unexplained = 0;
  double worst[5] = {};  // depth (relative), normal and depth gradient, barycentrics, motion, illumination (relative;
                         // these two beyond one half step)
};

double relative(double a, double b, double floor) {
  return std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), floor});
}

bool on_edge(const FrameInputs& in, std::size_t p) {
  const float b1 = as_float(in.visibility[4 * p + 2]), b2 = as_float(in.visibility[4 * p + 3]);
  return in.visibility[4 * p] != 0u && in.visibility[4 * p] != 0xFFFFFFFFu &&
         std::min({b1, b2, 1.0f - b1 - b2}) <= kOnEdge;
}

Explained explain(const FrameInputs& got, const FrameInputs& expected) {
  Explained e;
  for (std::size_t p = 0; p < std::size_t(got.width) * got.height; ++p) {
    const auto& a = got;
    const auto& b = expected;
    if (std::memcmp(&a.visibility[4 * p], &b.visibility[4 * p], 16) == 0 &&
        std::memcmp(&a.depth_normal[4 * p], &b.depth_normal[4 * p], 16) == 0 &&
        std::memcmp(&a.motion[4 * p], &b.motion[4 * p], 8) == 0 &&
        std::memcmp(&a.albedo[4 * p], &b.albedo[4 * p], 16) == 0 &&
        std::memcmp(&a.illumination[4 * p], &b.illumination[4 * p], 12) == 0) {
      ++e.identical;
      continue;
    }
    if (a.visibility[4 * p] != b.visibility[4 * p] || a.visibility[4 * p + 1] != b.visibility[4 * p + 1]) {
      if (on_edge(a, p) && on_edge(b, p))
        ++e.shared_edge;
      else
        ++e.unexplained;
      continue;
    }
    double d[5] = {relative(a.depth_normal[4 * p], b.depth_normal[4 * p], 1e-6), 0, 0, 0, 0};
    // The depth gradient and the octahedral normal as the G-buffer's texel holds them: a rounding
    // of their inputs may flip one step of the encoding (bfloat16: 2^-8 relative; snorm12: 1/2047).
    const double za = a.depth_normal[4 * p + 1], zb = b.depth_normal[4 * p + 1];
    d[1] = std::max(0.0, std::fabs(za - zb) - kGradientStep * std::max(std::fabs(za), std::fabs(zb)));
    for (int c = 2; c < 4; ++c)
      d[1] = std::max(
          d[1], std::fabs(double(a.depth_normal[4 * p + c]) - double(b.depth_normal[4 * p + c])) - kOctahedralStep);
    for (int c = 2; c < 4; ++c)
      d[2] = std::max(d[2], double(std::fabs(as_float(a.visibility[4 * p + c]) - as_float(b.visibility[4 * p + c]))));
    // Motion beyond one half step of its magnitude (in pixels).
    for (int c = 0; c < 2; ++c) {
      const double m = std::max(std::fabs(a.motion[4 * p + c]), std::fabs(b.motion[4 * p + c]));
      d[3] =
          std::max(d[3], std::max(0.0, double(std::fabs(a.motion[4 * p + c] - b.motion[4 * p + c])) - kHalfStep * m));
    }
    for (int c = 0; c < 3; ++c)
      d[4] = std::max(d[4], relative(a.illumination[4 * p + c], b.illumination[4 * p + c], 1e-3) - kHalfStep);
    const bool same_albedo = std::memcmp(&a.albedo[4 * p], &b.albedo[4 * p], 16) == 0;
    if (same_albedo && d[0] <= kDepthRelative && d[1] <= kNormalAbsolute && d[2] <= kBaryAbsolute &&
        d[3] <= kMotionPixels && d[4] <= kIlluminationRelative)
      ++e.rounding;
    else
      ++e.unexplained;
    for (int i = 0; i < 5; ++i) e.worst[i] = std::max(e.worst[i], d[i]);
  }
  return e;
}

}  // namespace

TEST_CASE(
    "OpenGL and OpenGL ES G-buffers and path-traced images differ from Vulkan's only by rounding and shared-edge "
    "ties") {
  ValidatedDevice vulkan;
  const std::uint32_t w = 48, h = 40;
  for (const auto flavour : {hal::gl::Flavour::Gl, hal::gl::Flavour::Gles}) {
    std::vector<std::string> messages;
    const auto gl = open_gl(flavour, messages);
    const std::string backend = flavour_name(flavour);
    for (const std::string animation : {"static", "boxes-move", "orbit"}) {
      CAPTURE(backend);
      CAPTURE(animation);
      const auto scene = scene::builtin_scene("cornell", animation);
      const FrameInputs expected = render_frame_inputs(*vulkan, scene, false, w, h, 5, 2);
      const FrameInputs got = render_frame_inputs(*gl, scene, false, w, h, 5, 2);
      const Explained e = explain(got, expected);
      MESSAGE(backend << " " << animation << ", " << w * h << " pixels: " << e.identical << " identical, " << e.rounding
                      << " rounding (worst: depth " << e.worst[0] << " relative, normal " << e.worst[1]
                      << ", barycentrics " << e.worst[2] << ", beyond one half step: motion " << e.worst[3]
                      << " px, illumination " << e.worst[4] << " relative), " << e.shared_edge << " shared-edge ties, "
                      << e.unexplained << " unexplained");
      CHECK(e.unexplained == 0);
      CHECK(e.shared_edge <= static_cast<int>(w * h / 500));  // ties are rare: rays must hit an edge within an ulp
    }
    for (const auto& m : messages) FAIL_CHECK(backend << " reported: " << m);
  }
}
