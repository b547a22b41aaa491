// report/error_map: each pixel's value is its relMSE term averaged over the frames (so the map's
// mean is the runs' mean relMSE), shrinking keeps the mean, and the colour scale rises with the error.
#include <doctest/doctest.h>

#include <numeric>

#include "report/error_map.hpp"
#include "report/metrics.hpp"

using namespace asvgf::report;

namespace {

// A w x h RGBA image whose pixel p has the value f(p, channel) in RGB.
template <class F>
std::vector<float> image(std::uint32_t w, std::uint32_t h, F f) {
  std::vector<float> v(std::size_t(w) * h * 4, 1.0f);
  for (std::size_t p = 0; p < std::size_t(w) * h; ++p)
    for (int c = 0; c < 3; ++c) v[4 * p + std::size_t(c)] = f(p, c);
  return v;
}

double mean(const ErrorMap& m) {
  return std::accumulate(m.values.begin(), m.values.end(), 0.0) / double(m.values.size());
}

}  // namespace

TEST_CASE(
    "error map: per pixel, the mean over frames of relMSE's term, so that the map's mean is the frames' mean relMSE") {
  const std::uint32_t w = 6, h = 4;
  const auto reference = image(w, h, [](std::size_t p, int c) { return 0.1f * float(p % 5) + 0.05f * float(c); });
  const auto a = image(w, h, [](std::size_t p, int c) { return 0.3f * float(p % 3) + 0.02f * float(c); });
  const auto b = image(w, h, [](std::size_t p, int c) { return 0.2f * float(p % 7) - 0.01f * float(c); });
  ErrorMap map = error_map(w, h);
  add_frame(map, a, reference);
  add_frame(map, b, reference);
  CHECK(map.frames == 2);
  // Pixel 7 by hand.
  double e = 0;
  for (int c = 0; c < 3; ++c)
    e += asvgf::render::relative_squared_error(a[4 * 7 + c], reference[4 * 7 + c]) / 6.0 +
         asvgf::render::relative_squared_error(b[4 * 7 + c], reference[4 * 7 + c]) / 6.0;
  CHECK(map.values[7] == doctest::Approx(e));
  const double frames_mean =
      (asvgf::render::relative_mse(a, reference) + asvgf::render::relative_mse(b, reference)) / 2.0;
  CHECK(mean(map) == doctest::Approx(frames_mean));
  CHECK_THROWS(add_frame(map, image(w, h + 1, [](std::size_t, int) { return 0.0f; }), reference));
}

TEST_CASE("error map: shrinking averages blocks (the mean kept where the factor divides the size)") {
  ErrorMap map = error_map(6, 4);
  for (std::size_t p = 0; p < map.values.size(); ++p) map.values[p] = double(p * p % 11);
  const ErrorMap half = shrink(map, 2);
  CHECK(half.width == 3);
  CHECK(half.height == 2);
  CHECK(half.values[0] == doctest::Approx((map.values[0] + map.values[1] + map.values[6] + map.values[7]) / 4.0));
  CHECK(mean(half) == doctest::Approx(mean(map)));
  // 4 does not divide 6: the edge blocks average the pixels they have (2 x 4 and 4 x 4 here).
  const ErrorMap quarter = shrink(map, 4);
  CHECK(quarter.width == 2);
  CHECK(quarter.height == 1);
  double edge = 0;
  for (std::uint32_t y = 0; y < 4; ++y) edge += map.values[y * 6 + 4] + map.values[y * 6 + 5];
  CHECK(quarter.values[1] == doctest::Approx(edge / 8.0));
  CHECK(shrink_factor(1920, 320) == 6);
  CHECK(shrink_factor(1921, 320) == 7);
  CHECK(shrink_factor(64, 320) == 1);
}

TEST_CASE("error map colours: the scale's top is the power of ten over the 99th percentile, brighter is worse") {
  ErrorMap map = error_map(100, 1);
  for (std::size_t p = 0; p < 100; ++p) map.values[p] = p == 99 ? 50.0 : 0.001 * double(p + 1);  // p99: 0.099
  const ErrorMap* maps[] = {&map};
  CHECK(error_scale_top(maps) == doctest::Approx(0.1));
  ErrorMap zeros = error_map(3, 1);
  const ErrorMap* none[] = {&zeros};
  CHECK(error_scale_top(none) == 1.0);

  auto brightness = [](Rgba c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
  const double top = 0.1;
  double last = -1;
  for (double v = top * 1e-4; v <= top; v *= 1.5) {
    const double b = brightness(error_colour(v, top));
    CHECK(b > last);
    last = b;
  }
  // Beyond the ends: the ends' colours; zero error is the bottom's.
  const Rgba bottom = error_colour(top * 1e-4, top), high = error_colour(top, top);
  CHECK(error_colour(0.0, top).r == bottom.r);
  CHECK(error_colour(top * 1e-9, top).g == bottom.g);
  CHECK(error_colour(top * 1e3, top).b == high.b);
  const auto rgba = error_colours(map, top);
  CHECK(rgba.size() == 400);
  CHECK(rgba[4 * 99 + 1] == high.g);
}
