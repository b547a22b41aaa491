// Summaries over a run's frames, the headline and report.csv.
#include "report/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <sstream>

namespace asvgf::report {
namespace {

std::string num(double v) {
  if (!std::isfinite(v)) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string short_num(double v, int digits = 3) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace

int RunSpec::history_ramp() const {
  if (method == frame::Method::Raw || accumulation()) return 0;
  return static_cast<int>(std::ceil(1.0 / static_cast<double>(denoise.alpha) - 1e-9));
}

void summarise(RunResult& run, std::optional<ChangeWindow> change) {
  std::vector<double> relmse, ssim, temporal, gpu, after, radiance, reference_radiance;
  std::map<std::string, std::vector<double>> passes;
  std::vector<std::string> order;
  for (const auto& f : run.frames) {
    relmse.push_back(f.relmse);
    ssim.push_back(f.ssim);
    temporal.push_back(f.temporal);
    gpu.push_back(f.gpu_ms.value_or(NAN));
    radiance.push_back(f.mean);
    reference_radiance.push_back(f.reference_mean);
    if (!change || f.frame >= change->first) after.push_back(f.relmse);
    for (const auto& [pass, ms] : f.pass_ms) {
      if (!passes.count(pass)) order.push_back(pass);
      passes[pass].push_back(ms);
    }
  }
  run.mean_relmse = mean(relmse);
  run.mean_ssim = mean(ssim);
  run.mean_temporal = mean(temporal);
  run.mean_relmse_after_change = mean(after);
  std::vector<double> textured, untextured;
  for (const auto& f : run.frames) textured.push_back(f.relmse_textured), untextured.push_back(f.relmse_untextured);
  run.mean_relmse_textured = mean(textured);
  run.mean_relmse_untextured = mean(untextured);
  std::vector<double> glossy, matte, glossy_after, matte_after;
  for (const auto& f : run.frames) {
    glossy.push_back(f.relmse_glossy), matte.push_back(f.relmse_matte);
    if (!change || f.frame >= change->first)
      glossy_after.push_back(f.relmse_glossy), matte_after.push_back(f.relmse_matte);
  }
  run.mean_relmse_glossy = mean(glossy);
  run.mean_relmse_matte = mean(matte);
  run.glossy_after_change = mean(glossy_after);
  run.matte_after_change = mean(matte_after);
  for (int k = 0; k < kPixelClasses; ++k) {
    std::vector<double> fraction, contribution;
    for (const auto& f : run.frames)
      fraction.push_back(f.classes.fraction[std::size_t(k)]),
          contribution.push_back(f.classes.contribution(PixelClass(k)));
    run.class_fraction[std::size_t(k)] = mean(fraction);
    run.class_contribution[std::size_t(k)] = mean(contribution);
  }
  run.gpu_ms = median(gpu);
  run.pass_ms.clear();
  for (const auto& p : order) run.pass_ms.emplace_back(p, median(passes[p]));
  run.lag = measure_lag(relmse, change);
  run.energy = energy_bias(radiance, reference_radiance, change, run.spec.history_ramp());
}

const RunResult* find_run(const ReportData& data, const std::string& name) {
  for (const auto& r : data.runs)
    if (r.spec.name == name) return &r;
  return nullptr;
}

namespace {
// The runs of `names` that are present, in that order.
std::vector<const RunResult*> runs_named(const ReportData& data, std::initializer_list<const char*> names) {
  std::vector<const RunResult*> runs;
  for (const char* name : names)
    if (const RunResult* r = find_run(data, name)) runs.push_back(r);
  return runs;
}
}  // namespace

std::vector<const RunResult*> change_crop_runs(const ReportData& data) {
  if (!data.change) return {};
  return runs_named(data, {"ema-0.05", "svgf", "asvgf"});
}

std::vector<const RunResult*> glossy_crop_runs(const ReportData& data) {
  if (data.reference_glossy_crops.empty()) return {};
  return runs_named(data, {"svgf", "asvgf", "asvgf-split", "asvgf-nodemod"});
}

Headline compute_headline(const ReportData& data) {
  Headline h;
  const RunResult* asvgf = find_run(data, "asvgf");
  std::vector<double> spp, err, ms;
  for (const auto& r : data.runs)
    if (r.spec.accumulation()) spp.push_back(r.spec.spp), err.push_back(r.mean_relmse), ms.push_back(r.gpu_ms);
  if (!asvgf || spp.size() < 2) {
    h.why_not = "needs the `asvgf` run and plain accumulation at two or more spp counts";
    h.text = "No headline: " + h.why_not + ".";
    return h;
  }
  h.available = true;
  h.asvgf_relmse = asvgf->mean_relmse;
  h.asvgf_ms = asvgf->gpu_ms;
  const CurveHit hit = interpolate_loglog(spp, err, h.asvgf_relmse);
  h.k = hit.x;
  h.beyond_max = hit.below_range;
  const bool timed =
      std::isfinite(h.asvgf_ms) && std::all_of(ms.begin(), ms.end(), [](double v) { return std::isfinite(v); });
  const std::string err_text = "(mean relMSE " + short_num(h.asvgf_relmse) + ")";
  if (h.k) {
    h.accumulation_ms = timed ? evaluate_loglog(spp, ms, *h.k) : NAN;
    h.speedup = h.accumulation_ms / h.asvgf_ms;
    h.text =
        "At 1 spp `asvgf` " + err_text + " reaches the error of plain accumulation at K = " + short_num(*h.k) + " spp";
    h.text += timed ? ", in " + short_num(h.speedup) + " times less GPU time (" + short_num(h.asvgf_ms) +
                          " ms against " + short_num(h.accumulation_ms) + " ms a frame)."
                    : "; no GPU times (the device has no timestamps).";
  } else if (hit.below_range) {
    h.accumulation_ms = ms.back();
    h.speedup = ms.back() / h.asvgf_ms;
    h.text = "At 1 spp `asvgf` " + err_text + " is below the error of plain accumulation at every measured spp: K > " +
             short_num(spp.back()) + " spp (raise --max-accumulation-spp)";
    h.text += timed
                  ? ", already " + short_num(h.speedup) + " times less GPU time than " + short_num(spp.back()) + " spp."
                  : ".";
  } else {
    h.text = "At 1 spp `asvgf` " + err_text + " does not reach the error of plain accumulation at " +
             short_num(spp.front()) + " spp (" + short_num(err.front()) + ").";
  }
  if (timed && data.cpu_device) h.text += " GPU times are CPU-emulated (" + data.device_name + "): no speed claim.";

  // Errors after a change mostly measure lag (and are ~0 once light-exit's room is dark), so also
  // compare on the frames before it, where every method sees the same still, lit scene.
  if (asvgf->lag.measured) {
    std::vector<double> before;
    for (const auto& r : data.runs)
      if (r.spec.accumulation()) before.push_back(r.lag.steady_error);
    const CurveHit b = interpolate_loglog(spp, before, asvgf->lag.steady_error);
    h.k_before_change = b.x;
    const std::string frames = "frames 1.." + std::to_string(asvgf->lag.change_frame - 1);
    h.before_change_text = "Before the change (" + frames + ", " + data.animation +
                           "'s still start; the histories are still short): `asvgf` has mean relMSE " +
                           short_num(asvgf->lag.steady_error) + ", ";
    if (b.x)
      h.before_change_text +=
          "plain accumulation's at K = " + short_num(*b.x) + " spp" +
          (timed ? " (" + short_num(evaluate_loglog(spp, ms, *b.x) / h.asvgf_ms) + " times the GPU time)" : "") + ".";
    else if (b.below_range)
      h.before_change_text += "below accumulation's at every measured spp (K > " + short_num(spp.back()) + ").";
    else
      h.before_change_text += "above accumulation's at " + short_num(spp.front()) + " spp.";
  }
  return h;
}

std::vector<std::string> pass_columns(const ReportData& data) {
  std::vector<const RunResult*> runs;
  for (const auto& r : data.runs) runs.push_back(&r);
  std::stable_sort(runs.begin(), runs.end(), [](auto* a, auto* b) { return a->pass_ms.size() > b->pass_ms.size(); });
  std::vector<std::string> passes;
  for (const RunResult* r : runs)
    for (const auto& [p, ms] : r->pass_ms)
      if (std::find(passes.begin(), passes.end(), p) == passes.end()) passes.push_back(p);
  return passes;
}

std::string report_csv(const ReportData& data) {
  const std::vector<std::string> passes = pass_columns(data);
  std::ostringstream csv;
  csv << "run,method,spp,alpha,adaptive,atrous_iterations,kernel,frame,relmse,ssim,temporal,mean,reference_mean,gpu_ms";
  constexpr PixelClass kShown[] = {PixelClass::Edge, PixelClass::Coloured, PixelClass::Grey};
  for (const PixelClass c : kShown) csv << "," << to_string(c) << "_fraction,relmse_" << to_string(c);
  for (const auto& p : passes) csv << "," << p << "_ms";
  csv << "\n";
  for (const auto& r : data.runs) {
    const auto& s = r.spec;
    const bool filtered = s.method == frame::Method::Svgf || s.method == frame::Method::Asvgf;
    const bool temporal = filtered || s.method == frame::Method::Ema;
    for (const auto& f : r.frames) {
      csv << s.name << "," << frame::to_string(s.method) << "," << s.spp << ","
          << (temporal ? num(s.denoise.alpha) : "") << ","
          << (temporal ? (s.method == frame::Method::Asvgf ? "1" : "0") : "") << ","
          << (filtered ? std::to_string(s.denoise.atrous_iterations) : "") << ","
          << (filtered ? (s.denoise.kernel == asvgf::AtrousKernel::Box ? "box" : "b3spline") : "") << "," << f.frame
          << "," << num(f.relmse) << "," << num(f.ssim) << "," << num(f.temporal) << "," << num(f.mean) << ","
          << num(f.reference_mean) << "," << (f.gpu_ms ? num(*f.gpu_ms) : "");
      for (const PixelClass c : kShown)
        csv << "," << num(f.classes.fraction[std::size_t(c)]) << "," << num(f.classes.relmse[std::size_t(c)]);
      for (const auto& p : passes) {
        const auto it = std::find_if(f.pass_ms.begin(), f.pass_ms.end(), [&](const auto& e) { return e.first == p; });
        csv << "," << (it != f.pass_ms.end() ? num(it->second) : "");
      }
      csv << "\n";
    }
  }
  return csv.str();
}

}  // namespace asvgf::report
