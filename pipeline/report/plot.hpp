// report/plot.hpp: line and scatter plots (linear or log axes, legend, shaded x range) drawn on a
// Canvas, and a labelled grid of image crops.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/canvas.hpp"

namespace asvgf::report {

struct Series {
  std::string label;
  std::vector<double> x, y;  // points with a non-finite (or, on a log axis, non-positive) value are skipped
  Rgba color;
  bool lines = true;  // connect consecutive points
  std::optional<Marker> marker;
  std::vector<std::string> point_labels;  // optional, drawn beside each point
  bool dashed = false;
};

struct PlotSpec {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  std::vector<Series> series;
  std::optional<std::pair<double, double>> shade_x;  // e.g. the frames while the scene changes
  std::string shade_label;
  std::string subtitle;        // grey line under the title (scene, size)
  std::string note;            // red line under that (e.g. "CPU-emulated GPU time")
  bool zeros_on_edge = false;  // log y: exact zeros drawn on the bottom edge (say so in `note`)
};

// Text and axis colour of every plot, and the grey of secondary text.
inline constexpr Rgba kInk{30, 30, 30, 255};
inline constexpr Rgba kSubtleInk{110, 110, 110, 255};

// The i-th colour and marker of a fixed palette (Tableau 10).
Rgba palette_color(std::size_t i);
Marker palette_marker(std::size_t i);

Canvas draw_plot(const PlotSpec& spec, std::uint32_t width = 960, std::uint32_t height = 600);

struct CropCell {
  std::vector<std::uint8_t> rgba;  // crop pixels, RGBA8
  std::uint32_t width = 0, height = 0;
};
// rows x columns of crops, each drawn at `zoom`, with row labels on the left and column labels on
// top. cells[r][c]; an empty cell is drawn grey.
Canvas draw_crop_grid(const std::string& title, const std::vector<std::string>& row_labels,
                      const std::vector<std::string>& column_labels, const std::vector<std::vector<CropCell>>& cells,
                      int zoom);

}  // namespace asvgf::report
