#include "report/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace asvgf::report {
namespace {

constexpr Rgba kGrid{225, 225, 225, 255};
constexpr Rgba kShade{255, 230, 190, 255};
constexpr int kText = 2;  // text scale: stb_easy_font is ~7 px high

std::string format_tick(double v) {
  char buf[32];
  if (v != 0.0 && (std::abs(v) < 1e-3 || std::abs(v) >= 1e5))
    std::snprintf(buf, sizeof buf, "%.0e", v);
  else
    std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// One axis: maps data values to pixels, linear or log10.
struct Axis {
  bool log = false;
  double lo = 0, hi = 1;       // in axis space (log10 when log)
  double p0 = 0, p1 = 1;       // pixel positions of lo and hi
  bool zeros_on_edge = false;  // log axis: draw exact zeros at lo's edge instead of dropping them

  bool valid(double v) const { return std::isfinite(v) && (!log || v > 0 || (zeros_on_edge && v == 0)); }
  double space(double v) const { return log ? std::log10(v) : v; }
  double to_pixel(double v) const { return log && v <= 0 ? p0 : p0 + (space(v) - lo) / (hi - lo) * (p1 - p0); }

  void fit(const std::vector<double>& values) {
    double mn = INFINITY, mx = -INFINITY;
    for (double v : values)
      if (valid(v) && (!log || v > 0)) mn = std::min(mn, space(v)), mx = std::max(mx, space(v));
    if (!std::isfinite(mn)) mn = 0, mx = 1;
    if (mx - mn < 1e-12) {
      const double pad = log ? 0.5 : std::max(std::abs(mn) * 0.1, 1e-3);
      mn -= pad, mx += pad;
    }
    const double pad = (mx - mn) * 0.06;
    lo = mn - pad, hi = mx + pad;
  }

  // Major ticks (labelled) and minor ticks (grid only), in data values.
  void ticks(std::vector<double>& major, std::vector<double>& minor) const {
    if (log) {
      const int d0 = int(std::floor(lo)), d1 = int(std::ceil(hi));
      const bool few = d1 - d0 <= 2;  // less than ~2 decades: also label 2 and 5
      for (int d = d0; d <= d1; ++d)
        for (int m = 1; m <= 9; ++m) {
          const double v = m * std::pow(10.0, d), s = std::log10(v);
          if (s < lo || s > hi) continue;
          (m == 1 || (few && (m == 2 || m == 5)) ? major : minor).push_back(v);
        }
      return;
    }
    const double span = hi - lo, raw = span / 6.0, mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2 * mag : raw / mag < 7.5 ? 5 * mag : 10 * mag;
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step)
      major.push_back(std::abs(v) < 1e-12 * span ? 0.0 : v);
  }
};

void draw_series_line(Canvas& c, const Series& s, const Axis& ax, const Axis& ay) {
  bool have = false;
  double px = 0, py = 0, dash_phase = 0;
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!ax.valid(s.x[i]) || !ay.valid(s.y[i])) {
      have = false;
      continue;
    }
    const double x = ax.to_pixel(s.x[i]), y = ay.to_pixel(s.y[i]);
    if (have) {
      if (!s.dashed) {
        c.line(px, py, x, y, s.color, 2.0);
      } else {  // 8 px on, 5 px off along the polyline
        const double len = std::hypot(x - px, y - py);
        for (double t = 0; t < len;) {
          const double period = std::fmod(dash_phase + t, 13.0), on = period < 8.0;
          const double step = std::min(len - t, on ? 8.0 - period : 13.0 - period);
          if (on)
            c.line(px + (x - px) * t / len, py + (y - py) * t / len, px + (x - px) * (t + step) / len,
                   py + (y - py) * (t + step) / len, s.color, 2.0);
          t += std::max(step, 1e-3);
        }
        dash_phase = std::fmod(dash_phase + len, 13.0);
      }
    }
    px = x, py = y, have = true;
  }
}

}  // namespace

Rgba palette_color(std::size_t i) {
  static constexpr Rgba colors[] = {
      {31, 119, 180, 255}, {255, 127, 14, 255},  {44, 160, 44, 255},   {214, 39, 40, 255},  {148, 103, 189, 255},
      {140, 86, 75, 255},  {227, 119, 194, 255}, {127, 127, 127, 255}, {188, 189, 34, 255}, {23, 190, 207, 255}};
  return colors[i % std::size(colors)];
}

Marker palette_marker(std::size_t i) {
  static constexpr Marker markers[] = {Marker::Circle, Marker::Square, Marker::Triangle, Marker::Diamond,
                                       Marker::Cross};
  return markers[i % std::size(markers)];
}

Canvas draw_plot(const PlotSpec& spec, std::uint32_t width, std::uint32_t height) {
  Canvas c(width, height);
  int legend_w = 0;
  for (const auto& s : spec.series) legend_w = std::max(legend_w, Canvas::text_width(s.label, kText));
  legend_w += 60;
  const int left = 100, top = 56 + (spec.subtitle.empty() ? 0 : 22) + (spec.note.empty() ? 0 : 22), bottom = 60;
  const int right = legend_w + 30;
  const int x0 = left, x1 = int(width) - right, y0 = top, y1 = int(height) - bottom;

  Axis ax{spec.log_x}, ay{spec.log_y};
  ay.zeros_on_edge = spec.zeros_on_edge;
  std::vector<double> xs, ys;
  for (const auto& s : spec.series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (ax.valid(s.x[i]) && ay.valid(s.y[i])) xs.push_back(s.x[i]), ys.push_back(s.y[i]);
  }
  if (spec.shade_x) xs.push_back(spec.shade_x->first), xs.push_back(spec.shade_x->second);
  ax.fit(xs);
  ay.fit(ys);
  ax.p0 = x0, ax.p1 = x1, ay.p0 = y1, ay.p1 = y0;

  if (spec.shade_x) {
    const double a = ax.to_pixel(spec.shade_x->first), b = ax.to_pixel(spec.shade_x->second);
    c.fill_rect(int(std::min(a, b)), y0, int(std::max(a, b)) + 1, y1, kShade);
    if (!spec.shade_label.empty()) c.text(int(std::min(a, b)) + 4, y0 + 4, spec.shade_label, {150, 90, 20, 255}, kText);
  }
  std::vector<double> xmaj, xmin, ymaj, ymin;
  ax.ticks(xmaj, xmin);
  ay.ticks(ymaj, ymin);
  for (double v : xmin) c.fill_rect(int(ax.to_pixel(v)), y0, int(ax.to_pixel(v)) + 1, y1, {240, 240, 240, 255});
  for (double v : ymin) c.fill_rect(x0, int(ay.to_pixel(v)), x1, int(ay.to_pixel(v)) + 1, {240, 240, 240, 255});
  for (double v : xmaj) {
    const int p = int(ax.to_pixel(v));
    c.fill_rect(p, y0, p + 1, y1, kGrid);
    c.fill_rect(p, y1, p + 1, y1 + 6, kInk);
    const std::string t = format_tick(v);
    c.text(p - Canvas::text_width(t, kText) / 2, y1 + 10, t, kInk, kText);
  }
  for (double v : ymaj) {
    const int p = int(ay.to_pixel(v));
    c.fill_rect(x0, p, x1, p + 1, kGrid);
    c.fill_rect(x0 - 6, p, x0, p + 1, kInk);
    const std::string t = format_tick(v);
    c.text(x0 - 10 - Canvas::text_width(t, kText), p - Canvas::text_height(kText) / 2, t, kInk, kText);
  }
  c.rect_outline(x0, y0, x1 + 1, y1 + 1, kInk);

  for (const auto& s : spec.series)
    if (s.lines) draw_series_line(c, s, ax, ay);
  for (const auto& s : spec.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!ax.valid(s.x[i]) || !ay.valid(s.y[i])) continue;
      const double px = ax.to_pixel(s.x[i]), py = ay.to_pixel(s.y[i]);
      if (s.marker) c.marker(px, py, *s.marker, 11, s.color);
      if (i < s.point_labels.size() && !s.point_labels[i].empty())
        c.text(int(px) + 7, int(py) + 5, s.point_labels[i], s.color, kText);
    }

  int line_y = 12;
  c.text(8, line_y, spec.title, kInk, kText);
  if (!spec.subtitle.empty()) c.text(8, line_y += 22, spec.subtitle, kSubtleInk, kText);
  if (!spec.note.empty()) c.text(8, line_y += 22, spec.note, {170, 40, 40, 255}, kText);
  c.text((x0 + x1 - Canvas::text_width(spec.x_label, kText)) / 2, y1 + 36, spec.x_label, kInk, kText);
  c.text(8, y0 - 20, spec.y_label, kInk, kText);

  // Legend to the right of the plot area.
  int ly = y0 + 4;
  const int lx = x1 + 16;
  for (const auto& s : spec.series) {
    if (s.label.empty()) continue;
    const double my = ly + 7;
    if (s.lines) {
      Series sample = s;
      sample.x = {0, 1};
      sample.y = {0, 0};
      Axis sx{false, 0, 1, double(lx), double(lx + 34)}, sy{false, 0, 1, my, my - 1};
      draw_series_line(c, sample, sx, sy);
    }
    if (s.marker) c.marker(lx + 17, my, *s.marker, 11, s.color);
    c.text(lx + 44, ly, s.label, kInk, kText);
    ly += 24;
  }
  return c;
}

Canvas draw_crop_grid(const std::string& title, const std::vector<std::string>& row_labels,
                      const std::vector<std::string>& column_labels, const std::vector<std::vector<CropCell>>& cells,
                      int zoom) {
  std::uint32_t cw = 1, ch = 1;
  for (const auto& row : cells)
    for (const auto& cell : row) cw = std::max(cw, cell.width), ch = std::max(ch, cell.height);
  int label_w = 0;
  for (const auto& l : row_labels) label_w = std::max(label_w, Canvas::text_width(l, kText));
  const int gap = 6, left = label_w + 20, top = 60;
  const int cell_w = int(cw) * zoom, cell_h = int(ch) * zoom;
  const std::size_t cols = column_labels.size();
  Canvas c(std::uint32_t(left + int(cols) * (cell_w + gap) + gap),
           std::uint32_t(top + int(cells.size()) * (cell_h + gap) + gap));
  c.text(10, 10, title, kInk, kText);
  for (std::size_t j = 0; j < cols; ++j)
    c.text(left + int(j) * (cell_w + gap), top - 22, column_labels[j], kInk, kText);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const int y = top + int(i) * (cell_h + gap);
    if (i < row_labels.size()) c.text(10, y + cell_h / 2 - 7, row_labels[i], kInk, kText);
    for (std::size_t j = 0; j < cols; ++j) {
      const int x = left + int(j) * (cell_w + gap);
      if (j < cells[i].size() && !cells[i][j].rgba.empty())
        c.blit(cells[i][j].rgba, cells[i][j].width, cells[i][j].height, x, y, zoom);
      else
        c.fill_rect(x, y, x + cell_w, y + cell_h, {200, 200, 200, 255});
    }
  }
  return c;
}

}  // namespace asvgf::report
