#include "report/summary.hpp"

#include <cmath>
#include <sstream>

#include "report/text.hpp"

namespace asvgf::report {
namespace {

std::string k_text(const ReportData& d, const RunResult& run) {
  if (run.spec.accumulation()) return number_text(run.spec.spp);
  const CurveHit hit = matching_accumulation(d, run.mean_relmse);
  if (hit.x) return number_text(*hit.x);
  double max_spp = 0;
  for (const auto& r : d.runs)
    if (r.spec.accumulation()) max_spp = std::max(max_spp, double(r.spec.spp));
  if (hit.below_range) return "> " + number_text(max_spp);
  if (hit.above_range) return "< 1";
  return "–";
}

}  // namespace

CurveHit matching_accumulation(const ReportData& data, double relmse) {
  std::vector<double> spp, err;
  for (const auto& r : data.runs)
    if (r.spec.accumulation()) spp.push_back(r.spec.spp), err.push_back(r.mean_relmse);
  if (spp.size() < 2) return {};
  return interpolate_loglog(spp, err, relmse);
}

bool summary_run(const RunSpec& spec) {
  return !spec.accumulation() && spec.summarised;
}

std::string summary_markdown(const std::vector<SceneReport>& scenes) {
  std::ostringstream out;
  out << "# A-SVGF across scenes\n\n";
  if (scenes.empty()) return out.str();
  const ReportData& first = scenes.front().data;
  out << first.width << "x" << first.height << ", " << first.frames << " frames of each scene's `" << first.animation
      << "` animation, reference " << first.reference_spp << " spp, on " << first.device_name << " ("
      << first.device_type << ")" << (first.cpu_device ? "; GPU times are CPU-emulated, no speed claim" : "")
      << ".\n\n";
  out << "Per scene and method: the means over all frames (relMSE and SSIM against the reference, temporal error), "
         "the lag after the animation's change, the energy bias, K (the plain-accumulation spp with the same mean "
         "relMSE: higher is better) and the median GPU time of a frame. Each scene's full report (every run, "
         "plots, crops, definitions) is linked.\n\n";
  out << "| scene | method | mean relMSE | mean SSIM | mean temporal error | lag (frames) | energy bias | K (spp) | "
      << (first.cpu_device ? "GPU ms (CPU-emulated)" : "GPU ms") << " |\n";
  out << "|---|---|---|---|---|---|---|---|---|\n";
  for (const SceneReport& s : scenes) {
    for (const RunResult& r : s.data.runs) {
      if (!summary_run(r.spec)) continue;
      out << "| [" << s.data.scene << "](" << s.folder << "/report.md) | " << r.spec.name << " | "
          << number_text(r.mean_relmse) << " | " << number_text(r.mean_ssim) << " | " << number_text(r.mean_temporal)
          << " | " << lag_text(r.lag, s.data.frames) << " | " << energy_text(r.energy) << " | " << k_text(s.data, r)
          << " | " << number_text(r.gpu_ms) << " |\n";
    }
  }
  out << "\n";
  for (const SceneReport& s : scenes) out << "- **" << s.data.scene << "**: " << s.headline.text << "\n";
  return out.str();
}

std::string summary_csv(const std::vector<SceneReport>& scenes) {
  std::ostringstream out;
  out << "scene,run,method,spp,mean_relmse,mean_ssim,mean_temporal,lag_frames,energy_bias,k_spp,gpu_ms\n";
  auto num = [](double v) { return std::isfinite(v) ? number_text(v, 9) : std::string(); };
  for (const SceneReport& s : scenes) {
    for (const RunResult& r : s.data.runs) {
      std::string k;
      if (!r.spec.accumulation()) {
        const CurveHit hit = matching_accumulation(s.data, r.mean_relmse);
        if (hit.x) k = num(*hit.x);
      }
      out << s.data.scene << "," << r.spec.name << "," << frame::to_string(r.spec.method) << "," << r.spec.spp << ","
          << num(r.mean_relmse) << "," << num(r.mean_ssim) << "," << num(r.mean_temporal) << ","
          << (r.lag.measured && r.lag.frames ? std::to_string(*r.lag.frames) : std::string()) << ","
          << (r.energy.bias ? num(*r.energy.bias) : std::string()) << "," << k << "," << num(r.gpu_ms) << "\n";
    }
  }
  return out.str();
}

}  // namespace asvgf::report
