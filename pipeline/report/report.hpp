// report/report.hpp: the results of `asvgf report` (runs of every method and setting over one
// animation, measured per frame against a reference) and what is written from them: report.csv,
// report.md and the PNG plots.
#pragma once

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "asvgf/denoise_settings.hpp"
#include "renderer/frame_graph.hpp"
#include "report/error_map.hpp"
#include "report/pixel_classes.hpp"
#include "report/plot.hpp"
#include "report/sequence_metrics.hpp"

namespace asvgf::report {

// One method with one setting, e.g. "ema-0.05" or "accum-8spp".
struct RunSpec {
  std::string name;         // short id: csv `run` column, plot legends
  std::string description;  // one line for the tables
  frame::Method method = frame::Method::Asvgf;
  std::uint32_t spp = 1;
  asvgf::DenoiseSettings denoise;
  bool demodulate = true;       // false: the denoiser filters radiance, albedo included (--no-demodulation)
  bool specular_split = false;  // glossy scenes: diffuse and specular filtered apart (--specular-split)
  bool own = false;             // from --run: rendered on every scene, as asked
  bool summarised = true;       // a row in --scenes' summary table (not the built-in variants' box and ema-0.05)
  bool accumulation() const { return method == frame::Method::Reference; }
  // Frames until the temporal history is saturated (alpha_eff = max(alpha, 1/n) reaches alpha);
  // 0 for methods without a history.
  int history_ramp() const;
};

struct FrameResult {
  int frame = 0;
  double relmse = 0, ssim = 0;
  double temporal = 0;                  // NaN on the first frame (no previous frame)
  double mean = 0, reference_mean = 0;  // mean RGB radiance of the frame and of its reference
  std::optional<double> gpu_ms;         // whole frame; empty without timestamps
  // relMSE over the pixels whose surface is textured and over the others (scenes with albedo
  // textures); NaN where the frame has none of them.
  double relmse_textured = NAN, relmse_untextured = NAN;
  // The same over the pixels whose surface is glossy (a GGX lobe) and the matte ones.
  double relmse_glossy = NAN, relmse_matte = NAN;
  ClassErrors classes;  // relMSE by pixel class (edges, coloured and grey surfaces, background)
  std::vector<std::pair<std::string, double>> pass_ms;  // in execution order
};

// The widest error map error_maps.png shows (larger images are box-averaged down to it).
constexpr std::uint32_t kErrorMapWidth = 320;

struct RunResult {
  RunSpec spec;
  std::vector<FrameResult> frames;
  std::map<int, CropCell> crops;         // display-image crops of the frames the report shows
  std::map<int, CropCell> glossy_crops;  // the same frames where reflections change most (glossy scenes)
  ErrorMap error_map;                    // per pixel, over the frames; shrunk to at most kErrorMapWidth wide
  // Filled by summarise():
  double mean_relmse = 0, mean_ssim = 0, mean_temporal = 0;
  double mean_relmse_after_change = 0;  // frames from the change on (all frames when none)
  double gpu_ms = 0;                    // median whole-frame GPU ms; NaN without timestamps
  double mean_relmse_textured = NAN, mean_relmse_untextured = NAN;
  double mean_relmse_glossy = NAN, mean_relmse_matte = NAN;
  // Glossy and matte pixels from the change on: reflections that lag behind a moving object or
  // light (ghosting) raise the first.
  double glossy_after_change = NAN, matte_after_change = NAN;
  // Per pixel class, over the frames: the share of the pixels, and the class's part of mean_relmse
  // (they sum to it).
  std::array<double, kPixelClasses> class_fraction{}, class_contribution{};
  std::vector<std::pair<std::string, double>> pass_ms;  // median per pass, in pass order
  Lag lag;
  EnergyBias energy;
};

struct ReportData {
  std::string scene, animation;
  std::uint32_t width = 0, height = 0, seed = 0;
  int frames = 0;
  std::uint32_t reference_spp = 0;  // as traced (rounded up to equal batches)
  int reference_renders = 0;        // distinct scene states rendered as references
  std::string device_name, device_type;
  bool cpu_device = false;  // lavapipe: GPU times are CPU-emulated
  bool timestamps = false;
  bool timed_separately = false;  // GPU times from a back-to-back pass of their own (asvgf report --timing)
  bool ray_query = false;
  std::optional<ChangeWindow> change;
  std::vector<int> crop_frames;
  std::string crop_note;  // which part of the image the crops show
  int crop_zoom = 1;
  std::vector<RunResult> runs;
  std::map<int, CropCell> reference_crops;
  std::map<int, CropCell> reference_glossy_crops;  // empty: no crops_glossy.png
  std::string glossy_crop_note;
  // Scenes with albedo textures: the fraction of pixels (over all frames) whose primary surface is
  // textured; 0 without textures (no texture section).
  double textured_fraction = 0;
  // Scenes with glossy materials: the same fraction for glossy surfaces; 0: no glossy section.
  double glossy_fraction = 0;
  std::string command_line;
  double wall_seconds = 0;
};

void summarise(RunResult& run, std::optional<ChangeWindow> change);

// "at 1 spp asvgf reaches the error of plain accumulation at K spp, in X times less GPU time".
struct Headline {
  bool available = false;
  std::string why_not;
  double asvgf_relmse = 0, asvgf_ms = 0;
  std::optional<double> k;  // matching accumulation spp
  bool beyond_max = false;  // asvgf's error is below the largest accumulation's
  double accumulation_ms = 0, speedup = 0;
  std::string text;  // the sentence for report.md and the console
  // The same comparison on the frames before the change only (lit room; empty without a change).
  std::optional<double> k_before_change;
  std::string before_change_text;
};
Headline compute_headline(const ReportData& data);

const RunResult* find_run(const ReportData& data, const std::string& name);
// The runs crops_change.png shows (ema-0.05, svgf, asvgf, those present; none without a change).
std::vector<const RunResult*> change_crop_runs(const ReportData& data);
// The runs crops_glossy.png shows (svgf, asvgf, asvgf-split, asvgf-nodemod, those present); none: no such plot.
std::vector<const RunResult*> glossy_crop_runs(const ReportData& data);

// Every pass any run timed, in execution order (the run with the most passes sets it).
std::vector<std::string> pass_columns(const ReportData& data);

// report.csv: one row per run and frame.
std::string report_csv(const ReportData& data);
// report.md, linking the plots written by write_plots().
std::string report_markdown(const ReportData& data, const Headline& headline);
// error_vs_time.png, relmse_per_frame.png, temporal_per_frame.png, ssim_per_frame.png, crops.png,
// crops_change.png (when the animation changes), crops_glossy.png (when it changes a glossy scene),
// error_maps.png (every run but plain accumulation: where its error is).
// Returns the file names written.
std::vector<std::string> write_plots(const ReportData& data, const Headline& headline,
                                     const std::filesystem::path& dir);

}  // namespace asvgf::report
