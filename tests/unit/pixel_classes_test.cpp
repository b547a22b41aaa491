// report/pixel_classes: the classes partition the image (their relMSE contributions sum to the
// frame's), edges are two pixels wide on both sides of a change of albedo or surface, a plane tilted
// away from the camera is no edge, and background is where there is no surface.
#include <doctest/doctest.h>

#include <vector>

#include "report/metrics.hpp"
#include "report/pixel_classes.hpp"

using namespace asvgf::report;

namespace {

struct Gbuffer {
  std::uint32_t w, h;
  std::vector<float> albedo, depth, normal;
  Gbuffer(std::uint32_t width, std::uint32_t height)
      : w(width), h(height), albedo(4 * w * h, 0.5f), depth(4 * w * h, 0.0f), normal(4 * w * h, 0.0f) {
    for (std::size_t p = 0; p < std::size_t(w) * h; ++p)
      depth[4 * p] = 2.0f, depth[4 * p + 1] = 0.01f, normal[4 * p + 2] = 1.0f;
  }
  std::size_t at(std::uint32_t x, std::uint32_t y) const { return std::size_t(y) * w + x; }
  std::vector<PixelClass> classes() const { return classify_pixels(albedo, depth, normal, w, h); }
};

}  // namespace

TEST_CASE("pixel classes: a coloured and a grey half, their edge two pixels wide on each side, and background") {
  Gbuffer g(10, 6);
  for (std::uint32_t y = 0; y < g.h; ++y)
    for (std::uint32_t x = 0; x < 5; ++x) {
      float* a = &g.albedo[4 * g.at(x, y)];
      a[0] = 0.6f, a[1] = 0.1f, a[2] = 0.1f;
    }
  const auto c = g.classes();
  for (std::uint32_t x = 0; x < g.w; ++x) {
    CAPTURE(x);
    const PixelClass want = x < 3 ? PixelClass::Coloured : x < 7 ? PixelClass::Edge : PixelClass::Grey;
    CHECK(c[g.at(x, 3)] == want);
  }

  SUBCASE("no surface is background, and its neighbours edges") {
    g.depth[4 * g.at(9, 0)] = 0.0f;
    const auto b = g.classes();
    CHECK(b[g.at(9, 0)] == PixelClass::Background);
    CHECK(b[g.at(7, 2)] == PixelClass::Edge);
    CHECK(b[g.at(9, 3)] == PixelClass::Grey);
  }
  SUBCASE("a normal turned by 15 degrees is an edge") {
    for (std::uint32_t x = 8; x < g.w; ++x)
      for (std::uint32_t y = 0; y < g.h; ++y)
        g.normal[4 * g.at(x, y)] = 0.2588f, g.normal[4 * g.at(x, y) + 2] = 0.9659f;
    CHECK(g.classes()[g.at(9, 3)] == PixelClass::Edge);
  }
}

TEST_CASE("pixel classes: a plane tilted away from the camera is one surface, a step in depth is an edge") {
  Gbuffer g(12, 4);
  for (std::uint32_t y = 0; y < g.h; ++y)
    for (std::uint32_t x = 0; x < g.w; ++x)
      g.depth[4 * g.at(x, y)] = 2.0f + 0.1f * float(x), g.depth[4 * g.at(x, y) + 1] = 0.1f;
  for (const PixelClass k : g.classes()) CHECK(k == PixelClass::Grey);
  for (std::uint32_t y = 0; y < g.h; ++y) g.depth[4 * g.at(11, y)] += 1.0f;
  CHECK(g.classes()[g.at(9, 1)] == PixelClass::Edge);
  CHECK(g.classes()[g.at(8, 1)] == PixelClass::Grey);
}

TEST_CASE("pixel classes: the classes' relMSE contributions sum to the frame's relMSE") {
  Gbuffer g(10, 6);
  for (std::uint32_t y = 0; y < g.h; ++y)
    for (std::uint32_t x = 0; x < 5; ++x) g.albedo[4 * g.at(x, y)] = 0.9f;
  g.depth[4 * g.at(0, 0)] = 0.0f;
  const auto classes = g.classes();
  std::vector<float> image(4 * classes.size()), reference(image.size());
  for (std::size_t i = 0; i < image.size(); ++i) {
    reference[i] = 0.1f * float(i % 7);
    image[i] = reference[i] + 0.03f * float(i % 5) - 0.05f;
  }
  const ClassErrors e = relmse_by_class(image, reference, classes);
  double sum = 0, fractions = 0;
  for (int k = 0; k < kPixelClasses; ++k) {
    CHECK(e.fraction[std::size_t(k)] > 0);
    sum += e.contribution(PixelClass(k));
    fractions += e.fraction[std::size_t(k)];
  }
  CHECK(fractions == doctest::Approx(1.0));
  CHECK(sum == doctest::Approx(asvgf::render::relative_mse(image, reference)).epsilon(1e-12));
}
