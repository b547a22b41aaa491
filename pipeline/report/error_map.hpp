// report/error_map.hpp: where in the image a run's error is. Each pixel's relMSE (relative_mse's
// term, mean over RGB) averaged over the frames, shrunk by box averages to a size a page can show,
// and coloured on a log scale shared by every run of the report (error_maps.png).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "report/canvas.hpp"

namespace asvgf::report {

struct ErrorMap {
  std::uint32_t width = 0, height = 0;
  std::vector<double> values;  // row-major, per pixel: mean over RGB and frames of (x - r)^2 / (r^2 + 0.01)
  int frames = 0;              // frames added
};

// An empty map of the image's size.
ErrorMap error_map(std::uint32_t width, std::uint32_t height);
// Adds one frame (RGBA floats, the map's size): after n frames each value is the mean of n terms.
void add_frame(ErrorMap& map, std::span<const float> image, std::span<const float> reference);

// The map with each factor x factor block (the last ones cut by the edge) averaged into one value:
// a block's value is the mean of its pixels' values, so the map's mean over pixels is kept when
// factor divides both sides.
ErrorMap shrink(const ErrorMap& map, std::uint32_t factor);
// The smallest factor that makes the map at most max_width wide (1 when it already is).
std::uint32_t shrink_factor(std::uint32_t width, std::uint32_t max_width);

// The top of the colour scale for maps shown together: 10^ceil(log10(v)) for v the 99th percentile
// of their values (the scale spans kErrorDecades decades below it); 1 when every value is 0.
constexpr int kErrorDecades = 4;
double error_scale_top(std::span<const ErrorMap* const> maps);
// RGBA8 pixels of the map, colour by log10(value) from top / 10^kErrorDecades (black) to top
// (light yellow); values beyond either end take its colour.
std::vector<std::uint8_t> error_colours(const ErrorMap& map, double top);
// The colour of one value on that scale (the legend's bar).
Rgba error_colour(double value, double top);

}  // namespace asvgf::report
