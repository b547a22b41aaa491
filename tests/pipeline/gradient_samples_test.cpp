// A-SVGF's re-shaded gradient samples: a sample carried into this frame is shaded at last frame's
// surface point with last frame's random numbers, so where nothing but the camera moved (diffuse
// surfaces, still lights) it must reproduce last frame's luminance exactly. Anything else is a
// spurious gradient that throws history away. It is shaded apart from the pixel it lands in, which
// keeps a fresh sample of its own: the illumination is svgf's, pixel for pixel.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "renderer/renderer.hpp"
#include "renderer/scene/builtin.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;

TEST_CASE(
    "gradient samples: on a camera-only animation every carried sample reproduces last frame's luminance, and every "
    "pixel keeps a fresh sample") {
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
  render::RenderSettings plain = s;
  plain.method = frame::Method::Svgf;
  render::Renderer svgf(*device, scene, plain);
  for (int f = 0; f < 5; ++f) {
    const auto img = r.render(f);
    const auto svgf_img = svgf.render(f);
    REQUIRE(img.aovs);
    REQUIRE(svgf_img.aovs);
    const auto& a = *img.aovs;
    CAPTURE(f);
    // Not one pixel of the illumination is a re-shaded sample: every one is the fresh path svgf traces.
    CHECK(a.illumination == svgf_img.aovs->illumination);
    if (f == 0) continue;
    REQUIRE(a.gradient_ran);
    for (std::uint32_t sy = 0; sy < gh; ++sy) {
      for (std::uint32_t sx = 0; sx < gw; ++sx) {
        const float* g = &a.gradient_samples[(std::size_t(sy) * gw + sx) * 4];
        if (g[1] < 0.0f) {  // no sample landed in this stratum
          CHECK(g[3] == 0.0f);
          continue;
        }
        const auto index = static_cast<std::uint32_t>(g[1]);
        REQUIRE(3 * sx + index % 3 < s.width);
        REQUIRE(3 * sy + index / 3 < s.height);
        CAPTURE(sx);
        CAPTURE(sy);
        CHECK(g[3] == 1.0f);  // z holds this frame's luminance of the re-shaded sample
        CHECK(std::abs(g[2] - g[0]) <= 1e-5 * std::max(std::abs(g[2]), std::abs(g[0])) + 1e-7);
        ++samples;
      }
    }
  }
  // Most strata get a sample on a slow orbit; a test that compared nothing would pass vacuously.
  CHECK(samples > std::size_t(gw) * gh * 4 / 3);
}
