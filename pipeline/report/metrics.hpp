// report/metrics.hpp: error of an image against a reference: relative MSE (with the usual 0.01
// guard in the denominator) and SSIM on tonemapped luminance (Wang et al. 2004).
#pragma once

#include <cstdint>
#include <span>

namespace asvgf::render {

// One value's term of relMSE: (x - r)^2 / (r^2 + 0.01).
inline double relative_squared_error(double x, double r) {
  return (x - r) * (x - r) / (r * r + 0.01);
}

// mean over pixels and RGB channels of relative_squared_error; images are RGBA floats.
double relative_mse(std::span<const float> image, std::span<const float> reference);
// The same over the pixels p with (mask[p] != 0) == selected; NaN when there are none.
double relative_mse(std::span<const float> image, std::span<const float> reference, std::span<const std::uint8_t> mask,
                    bool selected);

// Mean SSIM of the tonemapped luminance (x / (1 + x)), 7x7 box windows, C1 = (0.01)^2, C2 = (0.03)^2.
double ssim(std::span<const float> image, std::span<const float> reference, std::uint32_t width, std::uint32_t height);

// Mean of RGB over all pixels.
double mean_value(std::span<const float> image);

}  // namespace asvgf::render
