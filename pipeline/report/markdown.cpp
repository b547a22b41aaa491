// report.md: the headline, the setup, every run's numbers, one section per comparison of the seed
// document, and the definitions of the measures.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/report.hpp"
#include "report/text.hpp"

namespace asvgf::report {
namespace {

std::string g(double v, int digits = 3) {
  return number_text(v, digits);
}

class Md {
 public:
  explicit Md(const ReportData& d) : d_(d) {}
  std::ostringstream out;

  std::string time_header() const { return d_.cpu_device ? "GPU ms/frame (CPU-emulated)" : "GPU ms/frame"; }

  void run_table(const std::vector<const RunResult*>& runs) {
    out << "| run | what | mean relMSE | mean SSIM | mean temporal error | relMSE from the change on | lag (frames) | "
           "energy bias | "
        << time_header() << " |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const RunResult* r : runs)
      out << "| `" << r->spec.name << "` | " << r->spec.description << " | " << g(r->mean_relmse) << " | "
          << g(r->mean_ssim, 4) << " | " << g(r->mean_temporal) << " | " << g(r->mean_relmse_after_change) << " | "
          << lag_text(r->lag, d_.frames) << " | " << energy_text(r->energy) << " | " << g(r->gpu_ms) << " |\n";
    out << "\n";
  }

  std::vector<const RunResult*> pick(std::initializer_list<const char*> names) const {
    std::vector<const RunResult*> v;
    for (const char* n : names)
      if (const RunResult* r = find_run(d_, n)) v.push_back(r);
    return v;
  }

  // relMSE of frames [first, last] for the given runs, with the mean radiance against the reference's.
  void frame_table(const std::vector<const RunResult*>& runs, int first, int last) {
    if (runs.empty()) return;
    out << "| frame | reference mean radiance |";
    for (const RunResult* r : runs) out << " `" << r->spec.name << "` relMSE (mean radiance) |";
    out << "\n| --- | --- |";
    for (std::size_t i = 0; i < runs.size(); ++i) out << " --- |";
    out << "\n";
    for (int f = std::max(first, 0); f <= std::min(last, d_.frames - 1); ++f) {
      const auto& rf = runs.front()->frames[std::size_t(f)];
      out << "| " << f << (d_.change && f >= d_.change->first && f <= d_.change->last ? " (moving)" : "") << " | "
          << g(rf.reference_mean) << " |";
      for (const RunResult* r : runs) {
        const auto& fr = r->frames[std::size_t(f)];
        out << " " << g(fr.relmse) << " (" << g(fr.mean) << ") |";
      }
      out << "\n";
    }
    out << "\n";
  }

 private:
  const ReportData& d_;
};

}  // namespace

std::string report_markdown(const ReportData& d, const Headline& headline) {
  Md md(d);
  auto& out = md.out;
  out << "# A-SVGF report: error against GPU time\n\n";
  out << "**" << headline.text << "**\n\n";
  if (!headline.before_change_text.empty())
    out << headline.before_change_text << " The headline averages every frame, those after the change included, "
        << "where a method that lags has large errors (on `light-exit` a method that follows has ~0 once the room "
           "is dark).\n\n";
  if (d.cpu_device)
    out << "> The device is " << d.device_name << " (" << d.device_type
        << "): the graphics API run on the CPU. Its \"GPU\" times are CPU-emulated timestamps, useful to compare "
           "passes with each "
           "other on this machine and nothing else: they make no speed claim. Speed claims come from a real GPU.\n\n";

  out << "## Setup\n\n";
  out << "| | |\n| --- | --- |\n";
  out << "| scene / animation | `" << d.scene << "` |\n";
  out << "| size | " << d.width << "x" << d.height << " |\n";
  out << "| frames | " << d.frames << " |\n";
  out << "| reference | plain accumulation at " << d.reference_spp << " spp, " << d.reference_renders
      << " renders (frames with the same scene state share one), its own seed |\n";
  out << "| seed | " << d.seed << " (the same seed gives the same report.csv, GPU-time columns aside) |\n";
  out << "| device | " << d.device_name << " (" << d.device_type << "), tracing with "
      << (d.ray_query ? "ray queries" : "the software BVH") << (d.timestamps ? "" : ", no timestamps") << " |\n";
  if (d.change)
    out << "| scene changes | frames " << d.change->first << " to " << d.change->last
        << " differ from the frame before |\n";
  out << "| wall time | " << g(d.wall_seconds) << " s |\n";
  out << "| command | `" << d.command_line << "` |\n\n";

  std::vector<const RunResult*> all, accum;
  for (const auto& r : d.runs) (r.spec.accumulation() ? accum : all).push_back(&r);
  out << "## Every method and setting\n\n![error against GPU time](error_vs_time.png)\n\n";
  md.run_table(all);
  if (!accum.empty()) {
    out << "Plain accumulation (method `reference`: N independent samples a pixel, every frame from scratch):\n\n";
    md.run_table(accum);
    // The reference carries noise of its own: relMSE(acc_N) ~ e1/N + e1/R for relMSE e1 at 1 spp
    // (variance adds), so the curve flattens towards e1/R as N approaches R.
    out << "The reference has noise of its own: with relMSE e1 at 1 spp, accumulation at N spp measures about "
           "e1/N + e1/R against a reference of R spp, so errors near e1/R = "
        << g(accum.front()->mean_relmse / accum.front()->spec.spp / double(std::max(1u, d.reference_spp)))
        << " are the reference's noise, not the method's.\n\n";
  }

  out << "## The seed document's comparisons, measured\n\n";
  out << "### 1 spp, EMA 0.2, EMA 0.05 (ghosting), SVGF, A-SVGF and the reference\n\n";
  const auto seed_runs = md.pick({"raw", "ema-0.2", "ema-0.05", "svgf", "asvgf"});
  md.run_table(seed_runs);
  const RunResult *e02 = find_run(d, "ema-0.2"), *e005 = find_run(d, "ema-0.05");
  if (e02 && e005 && d.change)
    out << "Ghosting: from the change on (frame " << d.change->first << "), EMA 0.05 has relMSE "
        << g(e005->mean_relmse_after_change) << " against " << g(e02->mean_relmse_after_change) << " for EMA 0.2 (lag "
        << lag_text(e005->lag, d.frames) << " against " << lag_text(e02->lag, d.frames)
        << " frames). Before the change: " << g(e005->lag.steady_error) << " against " << g(e02->lag.steady_error)
        << (std::abs(e005->lag.steady_error - e02->lag.steady_error) <= 0.01 * e02->lag.steady_error
                ? " (the same: over their first frames both average the whole history, α = max(α, 1/frames), so "
                  "a lower α only acts once the history is longer than 1/α frames)"
                : "")
        << ".\n\n";
  out << "![crops of every method beside the reference](crops.png)\n\n";

  out << "### 9 against 15 à-trous iterations\n\n";
  const auto atrous_runs = md.pick({"asvgf", "asvgf-box9", "asvgf-box15"});
  if (atrous_runs.size() < 2) {
    out << "Not run (see --methods).\n\n";
  } else {
    out << "The seed filters with a 3x3 box kernel and 9 iterations and shows 15 breaking the structure; "
           "`asvgf-box9` and `asvgf-box15` use that kernel, `asvgf` is the default (the 5x5 B3 spline's 13 "
           "taps with |i| + |j| <= 2, 5 iterations). "
           "Iteration i samples 2^i pixels apart: at "
        << d.width << "x" << d.height << " iterations past "
        << int(std::ceil(std::log2(double(std::max(d.width, d.height))))) << " reach beyond the image.\n\n";
    md.run_table(atrous_runs);
    out << "| run | à-trous ms/frame (sum of the `atrous.*` passes) |\n| --- | --- |\n";
    for (const RunResult* r : atrous_runs) {
      double sum = 0;
      for (const auto& [p, ms] : r->pass_ms)
        if (p.rfind("atrous", 0) == 0) sum += ms;
      out << "| `" << r->spec.name << "` | " << g(sum) << " |\n";
    }
    out << "\n";
  }

  out << "### Constant against adaptive α on `light-exit`\n\n";
  const auto alpha_runs = md.pick({"svgf", "asvgf", "ema-0.2"});
  if (!d.change) {
    out << "Nothing changes in this animation, so there is no lag to measure; run with `--animation light-exit`.\n\n";
  } else if (alpha_runs.empty()) {
    out << "Not run (see --methods).\n\n";
  } else {
    out << "`svgf` blends with a constant α = 0.2; `asvgf` raises α towards 1 where the temporal gradient says the "
           "shading changed. The seed shows the room still lit under a constant α after the light left; here is "
           "the same, measured: relMSE per frame and mean radiance against the reference's.\n\n";
    md.frame_table(alpha_runs, d.change->first - 1, std::min(d.change->last + 6, d.frames - 1));
    for (const RunResult* r : alpha_runs)
      if (r->lag.measured) {
        const std::string margin = lag_margin_text(r->lag);
        out << "- `" << r->spec.name << "`: steady relMSE before the change " << g(r->lag.steady_error)
            << ", threshold " << g(r->lag.threshold) << ", peak after it " << g(r->lag.peak_error) << ", lag "
            << lag_text(r->lag, d.frames) << " frames" << (margin.empty() ? "" : " (" + margin + ")") << ".\n";
      }
    out << "\n";
    if (!change_crop_runs(d).empty()) out << "![crops while the scene changes](crops_change.png)\n\n";
  }

  out << "### A-SVGF without the renderer's help\n\n";
  const auto gradient_runs = md.pick({"svgf", "asvgf", "asvgf-reproj"});
  if (!find_run(d, "asvgf") || !find_run(d, "asvgf-reproj")) {
    out << "Not run (see --methods).\n\n";
  } else {
    out << "`asvgf` takes its temporal gradient from re-shaded samples: the path tracer shades one pixel per 3x3 "
           "stratum at last frame's surface point with last frame's random numbers (A-SVGF, Schied et al. 2018), "
           "which a renderer must be built for. `asvgf-reproj` estimates it without that help "
           "(`--gradient-source reprojected`): per stratum, this frame's noisy luminance against last frame's "
           "noisy luminance reprojected through the motion vectors, as Q2RTX's low-frequency gradient; the two "
           "carry independent noise, so even a static scene shows a gradient of the order of the noise. `svgf` "
           "(no gradient) bounds it from the other side.\n\n";
    md.run_table(gradient_runs);
    if (d.change) md.frame_table(gradient_runs, d.change->first - 1, std::min(d.change->last + 6, d.frames - 1));
  }

  out << "### Textures: does the filter blur them?\n\n";
  if (d.textured_fraction <= 0) {
    out << "The scene has no albedo textures (try `--scene textured`).\n\n";
  } else {
    out << "The seed document guessed that filtering \"would blur the texture\". SVGF filters illumination, the "
           "radiance divided by the surface's albedo (texture included), and multiplies the albedo back after "
           "filtering, so texture detail never enters the filter; `asvgf-nodemod` (`--no-demodulation`) filters "
           "the radiance itself. relMSE over the pixels whose primary surface is textured ("
        << g(100.0 * d.textured_fraction) << "% of the pixels over all frames) and over the others:\n\n";
    out << "| run | relMSE textured | relMSE untextured | textured / untextured |\n| --- | --- | --- | --- |\n";
    for (const auto& r : d.runs) {
      out << "| `" << r.spec.name << "` | " << g(r.mean_relmse_textured) << " | " << g(r.mean_relmse_untextured)
          << " | " << g(r.mean_relmse_textured / r.mean_relmse_untextured) << " |\n";
    }
    const RunResult* with = find_run(d, "asvgf");
    const RunResult* without = find_run(d, "asvgf-nodemod");
    if (with && without) {
      out << "\nOn textured surfaces `asvgf` has relMSE " << g(with->mean_relmse_textured) << " with demodulation and "
          << g(without->mean_relmse_textured) << " without it ("
          << g(without->mean_relmse_textured / with->mean_relmse_textured) << " times as much"
          << (without->mean_relmse_textured > 2.0 * with->mean_relmse_textured
                  ? ": filtering radiance blurs the texture, so the seed's guess holds without demodulation"
                  : "")
          << "); with demodulation the textured error is "
          << g(with->mean_relmse_textured / with->mean_relmse_untextured)
          << " times the untextured one. The crops (`crops.png`) show both runs beside the reference.\n\n";
    } else {
      out << "\n(`asvgf` and `asvgf-nodemod` are needed for the comparison; see --methods.)\n\n";
    }
  }

  out << "### Glossy surfaces: reflections and ghosting\n\n";
  if (d.glossy_fraction <= 0) {
    out << "The scene has no glossy materials (try `--scene glossy`).\n\n";
  } else {
    out << "Diffuse and glossy reflection share one signal in `svgf` and `asvgf`: the radiance is divided by "
           "the surface's directional albedo (its GGX part from Karis's split-sum fit); `asvgf-split` "
           "(`--specular-split`) filters the light the GGX lobe reflects apart from the rest (as Q2RTX and NRD "
           "do), each divided by its own albedo, with histories of its own. All are reprojected along the "
           "surface's motion. A reflection moves with what it reflects, not with the surface, so a history "
           "reprojected along the surface lags behind a moving object or light (ghosting). relMSE over the "
           "pixels whose primary surface is glossy ("
        << g(100.0 * d.glossy_fraction) << "% of the pixels over all frames) and over the matte ones"
        << (d.change ? ", over all frames and from the change on (frame " + std::to_string(d.change->first) + ")" : "")
        << ":\n\n";
    // The reference's own noise per class, as for accumulation above: about raw's relMSE (1 spp) / R.
    // Glossy pixels are the noisier input, so at a small R it takes a larger share of their error.
    const RunResult* raw = find_run(d, "raw");
    const double r_spp = double(std::max(1u, d.reference_spp));
    const double glossy_floor = raw ? raw->mean_relmse_glossy / r_spp : NAN;
    const double matte_floor = raw ? raw->mean_relmse_matte / r_spp : NAN;
    auto less_floor = [&](const RunResult& r) {
      const double gl = r.mean_relmse_glossy - glossy_floor, ma = r.mean_relmse_matte - matte_floor;
      return gl > 0 && ma > 0 ? g(gl / ma) : std::string("n/a");
    };
    out << "| run | relMSE glossy | relMSE matte | glossy / matte |"
        << (raw ? " the same less the reference's noise |" : "")
        << " glossy from the change on | matte from the change on |\n| --- | --- | --- | --- |" << (raw ? " --- |" : "")
        << " --- | --- |\n";
    for (const auto& r : d.runs) {
      out << "| `" << r.spec.name << "` | " << g(r.mean_relmse_glossy) << " | " << g(r.mean_relmse_matte) << " | "
          << g(r.mean_relmse_glossy / r.mean_relmse_matte) << " | ";
      if (raw) out << (&r == raw ? std::string("") : less_floor(r)) << " | ";
      out << g(r.glossy_after_change) << " | " << g(r.matte_after_change) << " |\n";
    }
    out << "\n";
    if (raw)
      out << "The reference (" << d.reference_spp << " spp) has noise of its own, about `raw`'s relMSE / "
          << d.reference_spp << ": " << g(glossy_floor) << " over the glossy pixels and " << g(matte_floor)
          << " over the matte ones, part of every run's measured error; the fifth column takes it out of both "
             "before dividing (n/a where a run is within it).\n\n";
    if (!glossy_crop_runs(d).empty())
      out << "Where the reflections change most (" << d.glossy_crop_note
          << "), the frames around the change:\n\n![glossy crops](crops_glossy.png)\n\n";
  }

  out << "### Where the error is: edges, coloured and grey surfaces\n\n"
         "Each pixel of each frame is classed from the G-buffer: an edge (within two pixels of another "
         "surface or albedo), a coloured surface (albedo channels more than 0.05 apart, which demodulation "
         "divides unevenly), a grey one, or background. Each class's part of the mean relMSE (the parts sum "
         "to it), and in brackets that part divided by the class's share of the pixels:\n\n";
  if (!d.runs.empty()) {
    constexpr PixelClass kShown[] = {PixelClass::Edge, PixelClass::Coloured, PixelClass::Grey, PixelClass::Background};
    const RunResult& first = d.runs.front();
    out << "| run | mean relMSE";
    for (const PixelClass c : kShown)
      out << " | " << to_string(c) << " (" << g(100.0 * first.class_fraction[std::size_t(c)]) << "% of the pixels)";
    out << " |\n| ---";
    for (int k = 0; k <= kPixelClasses; ++k) out << " | ---";
    out << " |\n";
    for (const auto& r : d.runs) {
      out << "| `" << r.spec.name << "` | " << g(r.mean_relmse);
      for (const PixelClass c : kShown) {
        const auto k = std::size_t(c);
        out << " | " << g(r.class_contribution[k]);
        if (r.class_fraction[k] > 0) out << " (" << g(r.class_contribution[k] / r.class_fraction[k]) << ")";
      }
      out << " |\n";
    }
    out << "\n";
  }
  out << "Each pixel's relMSE, the mean over the frames, for every run but plain accumulation (larger "
         "images box-averaged to at most "
      << kErrorMapWidth << " pixels wide), on one log scale of " << kErrorDecades
      << " decades whose top is the power of ten at or above the 99th percentile of the maps' values:\n\n"
         "![per-pixel error of every run](error_maps.png)\n\n";

  out << "## Per-frame error\n\n![relMSE per frame](relmse_per_frame.png)\n\n"
      << "![temporal error per frame](temporal_per_frame.png)\n\n![SSIM per frame](ssim_per_frame.png)\n\n";

  out << "## GPU time per pass" << (d.cpu_device ? " (CPU-emulated on " + d.device_name + ")" : "") << "\n\n";
  // Every iteration of a filter is its own pass; the table sums them per filter (report.csv has each).
  auto group_of = [](const std::string& pass) {
    const auto dot = pass.find('.');
    return dot == std::string::npos ? pass : pass.substr(0, dot);
  };
  std::vector<std::string> groups;
  for (const auto& p : pass_columns(d))
    if (std::find(groups.begin(), groups.end(), group_of(p)) == groups.end()) groups.push_back(group_of(p));
  out << "Median over the frames, in ms; `atrous` and `gradient_atrous` sum their iterations, `specular` the "
         "specular chain of `--specular-split` runs (report.csv has each pass)."
         "\n\n| run | frame |";
  for (const auto& p : groups) out << " " << p << " |";
  out << "\n| --- | --- |";
  for (std::size_t i = 0; i < groups.size(); ++i) out << " --- |";
  out << "\n";
  for (const auto& r : d.runs) {
    out << "| `" << r.spec.name << "` | " << g(r.gpu_ms) << " |";
    for (const auto& grp : groups) {
      double sum = 0;
      bool any = false;
      for (const auto& [p, ms] : r.pass_ms)
        if (group_of(p) == grp) sum += ms, any = true;
      out << " " << (any ? g(sum) : "") << " |";
    }
    out << "\n";
  }
  out << "\n";

  out << "## Definitions\n\n"
         "- **relMSE** of a frame: mean over pixels and RGB of (m − r)² / (r² + 0.01), m the method's linear "
         "radiance, r the reference's. \"mean relMSE\" averages the frames, frame 0 included (no history yet).\n"
         "- **SSIM**: mean SSIM of the tonemapped luminance l/(1+l), 7x7 windows, C1 = 0.01², C2 = 0.03².\n"
         "- **temporal error** of frame t ≥ 1: mean over pixels and RGB of ((m_t − m_{t−1}) − (r_t − r_{t−1}))² / "
         "(r_t² + 0.01): flicker and lag measured against the reference's own change, with relMSE's guard. Frames "
         "that share a reference render have r_t − r_{t−1} = 0 exactly.\n"
         "- **lag**: the change starts at frame c, the first frame whose scene state differs from the one before. "
         "The threshold is twice the method's mean relMSE over frames 1..c−1 (its error before the change; frame 0 "
         "has no history). The lag is the number of frames from c until the relMSE is back under the threshold and "
         "stays there to the last frame; \"> n\" when it is still above at the last frame. The lag's details give "
         "how near the deciding frames came to the threshold (error / threshold): near 1, a change of that size "
         "in one frame's error moves the lag by whole frames.\n"
         "- **GPU time**: from the HAL's timestamps around every pass (Renderer::timings()); whole frame = sum of "
         "its passes; the table gives the median over the frames. "
      << (d.timed_separately ? "Each run's frames were rendered a second time for timing, back to back after half a "
                               "second of warm-up and with nothing read back, so that the GPU kept its clock up. "
                             : "The frames were timed as rendered for the error measures, between their host work. ")
      << (d.cpu_device ? "On lavapipe these are CPU-emulated. " : "") << "\n"
      << "- **energy bias**: the run's mean linear radiance summed over the frames where its temporal history "
         "is saturated, over the reference's sum on the same frames, minus 1 (negative: the method loses energy). "
         "A frame counts from ceil(1/α) frames after frame 0 and after the change's last frame (until then the "
         "history averages uniformly, α_eff = max(α, 1/n)); every frame for `raw` and accumulation; never where the "
         "reference is black (on `light-exit` the room is dark once the light has left, so use `--animation "
         "static`). n/a when no frame counts.\n"
      << "- **K**: accumulation's mean relMSE against its spp, interpolated linearly in log-log between the two "
         "measured spp counts that bracket `asvgf`'s mean relMSE; its GPU time at K is interpolated the same way.\n";
  return out.str();
}

}  // namespace asvgf::report
