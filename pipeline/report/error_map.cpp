#include "report/error_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "report/metrics.hpp"

namespace asvgf::report {

ErrorMap error_map(std::uint32_t width, std::uint32_t height) {
  return ErrorMap{width, height, std::vector<double>(std::size_t(width) * height, 0.0), 0};
}

void add_frame(ErrorMap& map, std::span<const float> image, std::span<const float> reference) {
  if (image.size() != map.values.size() * 4 || reference.size() != image.size())
    throw std::invalid_argument("add_frame: the images are not the error map's size");
  const double n = double(map.frames);
  for (std::size_t p = 0; p < map.values.size(); ++p) {
    double e = 0.0;
    for (int c = 0; c < 3; ++c) e += render::relative_squared_error(image[4 * p + c], reference[4 * p + c]);
    map.values[p] = (map.values[p] * n + e / 3.0) / (n + 1.0);
  }
  ++map.frames;
}

std::uint32_t shrink_factor(std::uint32_t width, std::uint32_t max_width) {
  if (max_width == 0) throw std::invalid_argument("shrink_factor: max_width is 0");
  return std::max<std::uint32_t>(1, (width + max_width - 1) / max_width);
}

ErrorMap shrink(const ErrorMap& map, std::uint32_t factor) {
  if (factor == 0) throw std::invalid_argument("shrink: factor is 0");
  ErrorMap out = error_map((map.width + factor - 1) / factor, (map.height + factor - 1) / factor);
  out.frames = map.frames;
  std::vector<std::uint32_t> count(out.values.size(), 0);
  for (std::uint32_t y = 0; y < map.height; ++y)
    for (std::uint32_t x = 0; x < map.width; ++x) {
      const std::size_t o = std::size_t(y / factor) * out.width + x / factor;
      out.values[o] += map.values[std::size_t(y) * map.width + x];
      ++count[o];
    }
  for (std::size_t o = 0; o < out.values.size(); ++o) out.values[o] /= double(count[o]);
  return out;
}

double error_scale_top(std::span<const ErrorMap* const> maps) {
  std::vector<double> all;
  for (const ErrorMap* m : maps) all.insert(all.end(), m->values.begin(), m->values.end());
  std::erase_if(all, [](double v) { return !(v > 0.0) || !std::isfinite(v); });
  if (all.empty()) return 1.0;
  const std::size_t k = std::min(all.size() - 1, std::size_t(std::ceil(0.99 * double(all.size()))) - 1);
  std::nth_element(all.begin(), all.begin() + std::ptrdiff_t(k), all.end());
  return std::pow(10.0, std::ceil(std::log10(all[k])));
}

Rgba error_colour(double value, double top) {
  // Five stops of a dark-to-light ramp (close to matplotlib's "magma"): brightness rises with the
  // error, so the map reads in grey too.
  static constexpr std::array<std::array<double, 3>, 5> kStops{
      {{0, 0, 4}, {81, 18, 124}, {183, 55, 121}, {252, 137, 97}, {252, 253, 191}}};
  const double t = value > 0.0 ? std::clamp((std::log10(value / top) + kErrorDecades) / kErrorDecades, 0.0, 1.0) : 0.0;
  const double s = t * double(kStops.size() - 1);
  const std::size_t i = std::min(kStops.size() - 2, std::size_t(s));
  const double f = s - double(i);
  auto channel = [&](int c) {
    return std::uint8_t(std::lround(kStops[i][std::size_t(c)] * (1.0 - f) + kStops[i + 1][std::size_t(c)] * f));
  };
  return Rgba{channel(0), channel(1), channel(2), 255};
}

std::vector<std::uint8_t> error_colours(const ErrorMap& map, double top) {
  std::vector<std::uint8_t> rgba(map.values.size() * 4);
  for (std::size_t p = 0; p < map.values.size(); ++p) {
    const Rgba c = error_colour(map.values[p], top);
    rgba[4 * p] = c.r, rgba[4 * p + 1] = c.g, rgba[4 * p + 2] = c.b, rgba[4 * p + 3] = 255;
  }
  return rgba;
}

}  // namespace asvgf::report
