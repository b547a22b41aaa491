// The whole frame on the OpenGL backend (OpenGL 4.5 and OpenGL ES 3.1) against the Vulkan
// backend's software-BVH variant, which runs the same shaders from the same SPIR-V: every method,
// frames where the box moves (so A-SVGF's gradient passes run), HDR output compared per pixel.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gl/gl_device.hpp"
#include "pipeline/frame_parity.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;
using namespace frame_parity;

TEST_CASE(
    "every method's frames on OpenGL and OpenGL ES match Vulkan's software-BVH frames to the rounding of what they "
    "store") {
  ValidatedDevice vulkan;
  const frame::Method methods[] = {frame::Method::Raw, frame::Method::Ema, frame::Method::Svgf, frame::Method::Asvgf,
                                   frame::Method::Reference};
  // Vulkan's frames once for both flavours: each method's renderer compiles its pipelines anew.
  std::vector<std::vector<std::vector<float>>> vulkan_frames;
  for (const frame::Method method : methods) vulkan_frames.push_back(frames(*vulkan, method, 5));
  for (const auto flavour : {hal::gl::Flavour::Gl, hal::gl::Flavour::Gles}) {
    std::vector<std::string> messages;
    const auto gl = open_gl(flavour, messages);
    const std::string backend = flavour_name(flavour);
    for (std::size_t m = 0; m < std::size(methods); ++m) {
      const frame::Method method = methods[m];
      const std::string name(frame::to_string(method));
      CAPTURE(backend);
      CAPTURE(name);
      const auto& expected = vulkan_frames[m];
      const auto got = frames(*gl, method, 5);
      for (std::size_t f = 0; f < expected.size(); ++f) {
        const Difference d = compare(got[f], expected[f], pixel_tolerance(method));
        MESSAGE(backend << " " << name << " frame " << f << ": " << d.over << " pixels over " << pixel_tolerance(method)
                        << ", worst " << d.worst << ", mean " << d.mean);
        CHECK(d.mean < kUlps / 4);
        CHECK(d.over <= static_cast<int>(expected[f].size() / 4 / 100));  // at most 1% of pixels
      }
    }
    for (const auto& m : messages) FAIL_CHECK(backend << " reported: " << m);
  }
}
