// The whole frame on the OpenGL backend (OpenGL 4.5 and OpenGL ES 3.1) against the Vulkan
// backend's software-BVH variant, which runs the same shaders from the same SPIR-V: every method,
// frames where the box moves (so A-SVGF's gradient passes run), HDR output compared per pixel.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hal/validate.hpp"
#include "hal_gl/gl.hpp"
#include "render/renderer.hpp"
#include "scene/builtin.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;

namespace {

struct Difference {
  int over = 0;      // pixels whose luminance differs by more than kUlps fp16 ulps
  double worst = 0;  // largest relative luminance difference
  double mean = 0;   // mean relative luminance difference
};

// Histories and filter outputs are fp16: a value rounds to 2^-11 relative at each store, and the
// chain stores a pixel a handful of times, so four ulps bound what rounding alone explains.
constexpr double kUlps = 4.0 / 2048.0;

Difference compare(const std::vector<float>& a, const std::vector<float>& b) {
  Difference d;
  const std::size_t pixels = a.size() / 4;
  for (std::size_t p = 0; p < pixels; ++p) {
    auto lum = [p](const std::vector<float>& v) {
      return 0.2126 * v[4 * p] + 0.7152 * v[4 * p + 1] + 0.0722 * v[4 * p + 2];
    };
    const double la = lum(a), lb = lum(b);
    const double rel = std::fabs(la - lb) / std::max({std::fabs(la), std::fabs(lb), 1e-3});
    if (rel > kUlps) ++d.over;
    d.worst = std::max(d.worst, rel);
    d.mean += rel / static_cast<double>(pixels);
  }
  return d;
}

std::vector<std::vector<float>> frames(hal::Device& device, frame::Method method, int count) {
  render::RenderSettings s;
  s.method = method;
  s.width = 32;
  s.height = 24;
  s.seed = 5;
  s.spp = method == frame::Method::Reference ? 2 : 1;
  s.ray_query = false;
  const scene::Scene scene = scene::builtin_scene("cornell", "boxes-move");  // the renderer keeps a reference
  render::Renderer r(device, scene, s);
  std::vector<std::vector<float>> out;
  for (int f = 0; f < count; ++f) out.push_back(r.render(f).hdr);
  return out;
}

}  // namespace

TEST_CASE("every method's frames on OpenGL and OpenGL ES match Vulkan's software-BVH frames to fp16 rounding") {
  ValidatedDevice vulkan;
  const frame::Method methods[] = {frame::Method::Raw, frame::Method::Ema, frame::Method::Svgf, frame::Method::Asvgf,
                                   frame::Method::Reference};
  for (const auto flavour : {hal::gl::Flavour::Gl, hal::gl::Flavour::Gles}) {
    std::vector<std::string> messages;
    hal::gl::DeviceOptions options;
    options.flavour = flavour;
    options.on_message = [&messages](const std::string& m) { messages.push_back(m); };
    const auto gl = hal::validate::wrap(hal::gl::create_device(options));
    const std::string backend = flavour == hal::gl::Flavour::Gl ? "gl" : "gles";
    for (const frame::Method method : methods) {
      const std::string name(frame::to_string(method));
      CAPTURE(backend);
      CAPTURE(name);
      const auto expected = frames(*vulkan, method, 5);
      const auto got = frames(*gl, method, 5);
      for (std::size_t f = 0; f < expected.size(); ++f) {
        const Difference d = compare(got[f], expected[f]);
        MESSAGE(backend << " " << name << " frame " << f << ": " << d.over << " pixels over 4 fp16 ulps, worst "
                        << d.worst << ", mean " << d.mean);
        CHECK(d.mean < kUlps / 4);
        CHECK(d.over <= static_cast<int>(expected[f].size() / 4 / 100));  // at most 1% of pixels
      }
    }
    for (const auto& m : messages) FAIL_CHECK(backend << " reported: " << m);
  }
}
