#include "report/sequence_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace asvgf::report {

double temporal_error(std::span<const float> m, std::span<const float> mp, std::span<const float> r,
                      std::span<const float> rp) {
  if (m.size() != mp.size() || m.size() != r.size() || m.size() != rp.size() || m.size() % 4 != 0)
    throw std::invalid_argument("temporal_error: image sizes differ");
  double sum = 0.0;
  for (std::size_t i = 0; i < m.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c) {
      const double dm = double(m[i + c]) - double(mp[i + c]), dr = double(r[i + c]) - double(rp[i + c]);
      sum += (dm - dr) * (dm - dr) / (double(r[i + c]) * double(r[i + c]) + 0.01);
    }
  return m.empty() ? 0.0 : sum / double(m.size() / 4 * 3);
}

std::optional<ChangeWindow> find_change(const std::vector<bool>& changed) {
  std::optional<ChangeWindow> w;
  for (std::size_t t = 1; t < changed.size(); ++t) {
    if (!changed[t]) {
      if (w) break;  // the first run of changing frames only
      continue;
    }
    if (!w) w = ChangeWindow{int(t), int(t)};
    w->last = int(t);
  }
  return w;
}

Lag measure_lag(const std::vector<double>& error, std::optional<ChangeWindow> change) {
  Lag lag;
  if (!change) {
    lag.why_not = "nothing changes";
    return lag;
  }
  const int c = change->first;
  lag.change_frame = c;
  if (c <= 1) {
    lag.why_not = "no frames with history before the change";
    return lag;
  }
  if (c >= int(error.size())) {
    lag.why_not = "the change is after the last frame";
    return lag;
  }
  lag.steady_error = mean(std::vector<double>(error.begin() + 1, error.begin() + c));
  lag.threshold = 2.0 * lag.steady_error;
  lag.measured = true;
  int settled = int(error.size());
  for (int t = int(error.size()) - 1; t >= c && error[std::size_t(t)] <= lag.threshold; --t) settled = t;
  if (settled < int(error.size())) lag.frames = settled - c;
  for (std::size_t t = std::size_t(c); t < error.size(); ++t) lag.peak_error = std::max(lag.peak_error, error[t]);
  if (lag.threshold > 0) {
    for (std::size_t t = std::size_t(settled); t < error.size(); ++t)
      lag.settled_ratio = std::max(lag.settled_ratio.value_or(0.0), error[t] / lag.threshold);
    if (settled > c) lag.last_over_ratio = error[std::size_t(settled - 1)] / lag.threshold;
  }
  return lag;
}

CurveHit interpolate_loglog(const std::vector<double>& xs, const std::vector<double>& ys, double target) {
  CurveHit hit;
  if (xs.empty() || xs.size() != ys.size() || !(target > 0)) return hit;
  double lowest = INFINITY, highest = 0;
  for (double y : ys) lowest = std::min(lowest, y), highest = std::max(highest, y);
  if (target < lowest) {
    hit.below_range = true;
    return hit;
  }
  if (target > highest && target > ys.front()) {
    hit.above_range = true;
    return hit;
  }
  // The first segment that brackets the target (the curve may wiggle from the reference's noise).
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double ya = ys[i], yb = ys[i + 1];
    if ((ya >= target && yb <= target) || (ya <= target && yb >= target)) {
      const double la = std::log(ya), lb = std::log(yb);
      const double t = lb == la ? 0.0 : (std::log(target) - la) / (lb - la);
      hit.x = std::exp(std::log(xs[i]) + t * (std::log(xs[i + 1]) - std::log(xs[i])));
      return hit;
    }
  }
  if (ys.size() == 1 || target == ys.front()) hit.x = xs.front();
  return hit;
}

double evaluate_loglog(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (xs.empty() || xs.size() != ys.size()) return NAN;
  if (xs.size() == 1) return ys.front();
  std::size_t i = 0;
  while (i + 2 < xs.size() && x > xs[i + 1]) ++i;
  const double t = (std::log(x) - std::log(xs[i])) / (std::log(xs[i + 1]) - std::log(xs[i]));
  return std::exp(std::log(ys[i]) + t * (std::log(ys[i + 1]) - std::log(ys[i])));
}

EnergyBias energy_bias(const std::vector<double>& mean, const std::vector<double>& reference_mean,
                       std::optional<ChangeWindow> change, int ramp) {
  EnergyBias e;
  double sum = 0, reference_sum = 0;
  for (std::size_t t = 0; t < mean.size() && t < reference_mean.size(); ++t) {
    const int f = static_cast<int>(t);
    const bool saturated = f >= ramp && (!change || f < change->first || f - change->last >= ramp);
    if (!saturated || !(reference_mean[t] > 0) || !std::isfinite(mean[t])) continue;
    sum += mean[t];
    reference_sum += reference_mean[t];
    ++e.frames;
  }
  if (e.frames > 0) e.bias = sum / reference_sum - 1.0;
  return e;
}

double mean(const std::vector<double>& v) {
  double sum = 0;
  int n = 0;
  for (double x : v)
    if (std::isfinite(x)) sum += x, ++n;
  return n ? sum / n : NAN;
}

double median(std::vector<double> v) {
  std::erase_if(v, [](double x) { return !std::isfinite(x); });
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace asvgf::report
