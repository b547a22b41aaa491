// report/pixel_classes.hpp: where in the image the error is. Each pixel of a frame is classed from
// the G-buffer the denoiser sees (albedo, depth and its gradient, normal) as an edge (within two
// pixels of another surface or albedo), a coloured surface (albedo channels more than 0.05 apart:
// what demodulation divides unevenly), a grey surface, or background (no surface). The classes
// partition the image, so their relMSE contributions sum to the frame's relMSE.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace asvgf::report {

enum class PixelClass : std::uint8_t { Background, Edge, Coloured, Grey };
inline constexpr int kPixelClasses = 4;
std::string_view to_string(PixelClass c);

// albedo, depth (z, dz: depth gradient a pixel; z = 0 without a surface) and normal: RGBA floats.
std::vector<PixelClass> classify_pixels(std::span<const float> albedo, std::span<const float> depth,
                                        std::span<const float> normal, std::uint32_t width, std::uint32_t height);

struct ClassErrors {
  std::array<double, kPixelClasses> fraction{};  // of the pixels
  std::array<double, kPixelClasses> relmse{};    // over the class's pixels; NaN where it has none
  // fraction * relmse: the class's part of the frame's relMSE (0 where it has no pixels).
  double contribution(PixelClass c) const;
};
ClassErrors relmse_by_class(std::span<const float> image, std::span<const float> reference,
                            std::span<const PixelClass> classes);

}  // namespace asvgf::report
