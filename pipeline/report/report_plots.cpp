// The report's PNG plots: error against GPU time, per-frame curves, crop grids.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/report.hpp"

namespace asvgf::report {
namespace {

constexpr Rgba kAccumulation{40, 40, 40, 255};

std::string g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// The runs that get their own line in the per-frame plots: every filtered method and the
// accumulation closest (in log spp) to `asvgf`'s error.
std::vector<const RunResult*> per_frame_runs(const ReportData& d, const Headline& h) {
  std::vector<const RunResult*> v;
  const RunResult* closest = nullptr;
  for (const auto& r : d.runs) {
    if (!r.spec.accumulation()) {
      v.push_back(&r);
      continue;
    }
    const double k = h.k ? *h.k : 1.0;
    if (!closest || std::abs(std::log(double(r.spec.spp) / k)) < std::abs(std::log(double(closest->spec.spp) / k)))
      closest = &r;
  }
  if (closest) v.push_back(closest);
  return v;
}

Series frame_series(const ReportData& d, const RunResult& r, std::size_t index, double FrameResult::*field) {
  Series s;
  s.label = r.spec.name;
  s.color = r.spec.accumulation() ? kAccumulation : palette_color(index);
  s.dashed = r.spec.accumulation();
  s.marker = palette_marker(index);
  for (const auto& f : r.frames) s.x.push_back(f.frame), s.y.push_back(f.*field);
  (void)d;
  return s;
}

PlotSpec per_frame_plot(const ReportData& d, const Headline& h, const std::string& title, const std::string& y_label,
                        double FrameResult::*field, bool log_y) {
  PlotSpec p;
  p.title = title;
  p.subtitle =
      d.scene + ", " + std::to_string(d.width) + "x" + std::to_string(d.height) + ", seed " + std::to_string(d.seed);
  p.x_label = "frame";
  p.y_label = y_label;
  p.log_y = log_y;
  if (log_y) {
    p.zeros_on_edge = true;
    p.note = "exact zeros (a black frame matching a black reference) on the bottom edge";
  }
  if (d.change) {
    p.shade_x = std::pair<double, double>(d.change->first - 0.5, d.change->last + 0.5);
    p.shade_label = "scene changes";
  }
  std::size_t i = 0;
  for (const RunResult* r : per_frame_runs(d, h)) p.series.push_back(frame_series(d, *r, i++, field));
  return p;
}

// error_maps.png: each run's map (every run but plain accumulation) in a grid, captioned with its
// name and mean relMSE, on one colour scale, with the scale's bar and decades below.
Canvas draw_error_maps(const ReportData& d) {
  std::vector<const RunResult*> runs;
  std::vector<const ErrorMap*> maps, filtered;  // the scale follows the filtered runs (raw's saturate)
  for (const auto& r : d.runs) {
    if (r.error_map.values.empty()) continue;  // plain accumulation has none
    runs.push_back(&r), maps.push_back(&r.error_map);
    if (r.spec.method != frame::Method::Raw) filtered.push_back(&r.error_map);
  }
  const double top = error_scale_top(filtered.empty() ? maps : filtered);
  constexpr int kScale = 2, kGap = 12, kCaption = 44;
  const std::uint32_t mw = maps.empty() ? 1 : maps.front()->width, mh = maps.empty() ? 1 : maps.front()->height;
  const int zoom = std::max(1, 192 / int(mw));
  const int cw = int(mw) * zoom, ch = int(mh) * zoom;
  const int columns = std::max(1, std::min(4, int(runs.size())));
  const int rows = (int(runs.size()) + columns - 1) / columns;
  const int top_y = 60, bar_h = 16;
  const int width = std::max(kGap + columns * (cw + kGap), 620);
  Canvas c(std::uint32_t(width), std::uint32_t(top_y + rows * (ch + kCaption + kGap) + bar_h + 60));
  c.text(10, 10,
         "per-pixel relMSE, mean over " + std::to_string(d.frames) + " frames (" + std::to_string(d.width) + "x" +
             std::to_string(d.height) +
             (mw < d.width ? ", box-averaged to " + std::to_string(mw) + "x" + std::to_string(mh) : std::string()) +
             ")",
         kInk, kScale);
  c.text(10, 32, d.scene + ", one log scale for every map, set by the filtered runs", kSubtleInk, kScale);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const int x = kGap + int(i % std::size_t(columns)) * (cw + kGap);
    const int y = top_y + int(i / std::size_t(columns)) * (ch + kCaption + kGap);
    c.text(x, y, runs[i]->spec.name, kInk, kScale);
    c.text(x, y + 20, "mean " + g(runs[i]->mean_relmse), kSubtleInk, kScale);
    c.blit(error_colours(*maps[i], top), mw, mh, x, y + kCaption, zoom);
  }
  // The scale: one bar, a tick and a label at each decade.
  const int bx = kGap, by = top_y + rows * (ch + kCaption + kGap), bw = width - 2 * kGap - 40;
  for (int x = 0; x < bw; ++x) {
    const double value = top * std::pow(10.0, kErrorDecades * (double(x) / double(bw - 1) - 1.0));
    c.fill_rect(bx + x, by, bx + x + 1, by + bar_h, error_colour(value, top));
  }
  for (int k = 0; k <= kErrorDecades; ++k) {
    const int x = bx + (bw - 1) * k / kErrorDecades;
    c.fill_rect(x, by + bar_h, x + 1, by + bar_h + 5, kInk);
    const std::string label = (k == 0               ? "<= "
                               : k == kErrorDecades ? ">= "
                                                    : "") +
                              g(top * std::pow(10.0, double(k - kErrorDecades)));
    c.text(std::clamp(x - Canvas::text_width(label, kScale) / 2, bx, width - Canvas::text_width(label, kScale) - 4),
           by + bar_h + 8, label, kInk, kScale);
  }
  return c;
}

}  // namespace

std::vector<std::string> write_plots(const ReportData& d, const Headline& h, const std::filesystem::path& dir) {
  std::vector<std::string> written;
  auto save = [&](const Canvas& c, const std::string& name) {
    c.write_png(dir / name);
    written.push_back(name);
  };

  {  // Error against GPU time, log-log: accumulation as a curve, every other run as a point.
    PlotSpec p;
    p.title = "mean relMSE against GPU time per frame";
    p.subtitle = d.scene + ", " + std::to_string(d.width) + "x" + std::to_string(d.height) + ", " +
                 std::to_string(d.frames) + " frames, reference " + std::to_string(d.reference_spp) + " spp";
    if (d.cpu_device) p.note = "GPU times CPU-emulated on " + d.device_name + ": no speed claim";
    p.x_label = d.cpu_device ? "GPU ms per frame (CPU-emulated, median)" : "GPU ms per frame (median)";
    p.y_label = "mean relMSE";
    p.log_x = p.log_y = true;
    Series acc;
    acc.label = "accumulation (N spp)";
    acc.color = kAccumulation;
    acc.marker = Marker::Circle;
    std::size_t i = 0;
    for (const auto& r : d.runs) {
      if (r.spec.accumulation()) {
        acc.x.push_back(r.gpu_ms), acc.y.push_back(r.mean_relmse);
        acc.point_labels.push_back(std::to_string(r.spec.spp));
        continue;
      }
      Series s;
      s.label = r.spec.name;
      s.color = palette_color(i);
      s.marker = palette_marker(i);
      ++i;
      s.lines = false;
      s.x = {r.gpu_ms};
      s.y = {r.mean_relmse};
      p.series.push_back(s);
    }
    if (!acc.x.empty()) p.series.insert(p.series.begin(), acc);
    if (h.k && std::isfinite(h.accumulation_ms)) {
      Series k;
      k.label = "K = " + g(*h.k) + " spp";
      k.color = {214, 39, 40, 255};
      k.marker = Marker::Cross;
      k.lines = false;
      k.x = {h.accumulation_ms};
      k.y = {h.asvgf_relmse};
      p.series.push_back(k);
    }
    save(draw_plot(p), "error_vs_time.png");
  }
  save(draw_plot(per_frame_plot(d, h, "relMSE per frame", "relMSE", &FrameResult::relmse, true)),
       "relmse_per_frame.png");
  save(draw_plot(per_frame_plot(d, h, "temporal error per frame", "temporal error", &FrameResult::temporal, true)),
       "temporal_per_frame.png");
  save(draw_plot(per_frame_plot(d, h, "SSIM per frame", "SSIM", &FrameResult::ssim, false)), "ssim_per_frame.png");

  // Crops: the reference on top, then every run shown in the per-frame plots.
  // `reference` and `crops` pick which crops: the default region's or the glossy one's.
  using Crops = std::map<int, CropCell>;
  auto grid = [&](const std::string& title, const std::vector<const RunResult*>& runs, const std::vector<int>& frames,
                  const std::string& name, const Crops& reference, Crops RunResult::*crops) {
    auto cell = [&](const Crops& m, int f) {
      const auto it = m.find(f);
      return it != m.end() ? it->second : CropCell{};
    };
    std::vector<std::string> rows{"reference"}, cols;
    std::vector<std::vector<CropCell>> cells(1);
    for (int f : frames) {
      cols.push_back("frame " + std::to_string(f));
      cells[0].push_back(cell(reference, f));
    }
    for (const RunResult* r : runs) {
      rows.push_back(r->spec.name);
      cells.emplace_back();
      for (int f : frames) cells.back().push_back(cell(r->*crops, f));
    }
    save(draw_crop_grid(title, rows, cols, cells, d.crop_zoom), name);
  };
  const auto runs = per_frame_runs(d, h);
  grid("every method beside the reference (" + d.crop_note + ")", runs, d.crop_frames, "crops.png", d.reference_crops,
       &RunResult::crops);
  if (d.change) {
    const auto alpha = change_crop_runs(d);
    std::vector<int> frames;
    for (int f = std::max(0, d.change->first - 1); f <= std::min(d.frames - 1, d.change->last + 3); ++f)
      frames.push_back(f);
    if (!alpha.empty())
      grid("constant (ema-0.05, svgf) against adaptive (asvgf) alpha while the scene changes (" + d.crop_note + ")",
           alpha, frames, "crops_change.png", d.reference_crops, &RunResult::crops);
    if (const auto glossy = glossy_crop_runs(d); !glossy.empty())
      grid("glossy surfaces where the reflections change most (" + d.glossy_crop_note + ")", glossy, frames,
           "crops_glossy.png", d.reference_glossy_crops, &RunResult::glossy_crops);
  }
  save(draw_error_maps(d), "error_maps.png");
  return written;
}

}  // namespace asvgf::report
