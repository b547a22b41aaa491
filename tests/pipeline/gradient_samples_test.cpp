// A-SVGF's re-shaded gradient samples: a sample carried into this frame is shaded at last frame's
// surface point with last frame's random numbers, so where nothing but the camera moved (diffuse
// surfaces, still lights) it must reproduce last frame's luminance exactly. Anything else is a
// spurious gradient that throws history away.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>

#include "renderer/renderer.hpp"
#include "renderer/scene/builtin.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;

namespace {

double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

}  // namespace

TEST_CASE("gradient samples: on a camera-only animation every carried sample reproduces last frame's luminance") {
  ValidatedDevice device;
  // cornell/orbit: the camera moves, the diffuse room and its light stay, so a re-shaded path is
  // the same path. 34x26 leaves partial strata on the right and bottom edges.
  const auto scene = scene::builtin_scene("cornell", "orbit");
  render::RenderSettings s;
  s.method = frame::Method::Asvgf;
  s.width = 34;
  s.height = 26;
  s.seed = 3;
  s.aovs = true;
  render::Renderer r(*device, scene, s);
  const std::uint32_t gw = (s.width + 2) / 3, gh = (s.height + 2) / 3;
  std::size_t samples = 0;
  // From frame 2 on, some of last frame's pixels shaded a carried sample themselves: their
  // visibility is not the point they shaded, so they must not be picked again.
  for (int f = 0; f < 5; ++f) {
    const auto img = r.render(f);
    REQUIRE(img.aovs);
    const auto& a = *img.aovs;
    if (f == 0) continue;
    REQUIRE(a.gradient_ran);
    for (std::uint32_t sy = 0; sy < gh; ++sy) {
      for (std::uint32_t sx = 0; sx < gw; ++sx) {
        const float* g = &a.gradient_samples[(std::size_t(sy) * gw + sx) * 4];
        if (g[1] < 0.0f) continue;  // no sample landed in this stratum
        const auto index = static_cast<std::uint32_t>(g[1]);
        const std::uint32_t px = 3 * sx + index % 3, py = 3 * sy + index / 3;
        REQUIRE(px < s.width);
        REQUIRE(py < s.height);
        const double now = luminance(&a.illumination[(std::size_t(py) * s.width + px) * 4]);
        CAPTURE(f);
        CAPTURE(px);
        CAPTURE(py);
        CHECK(std::abs(now - g[0]) <= 1e-5 * std::max(std::abs(now), double(g[0])) + 1e-7);
        ++samples;
      }
    }
  }
  // Most strata get a sample on a slow orbit; a test that compared nothing would pass vacuously.
  CHECK(samples > std::size_t(gw) * gh * 4 / 3);
}
