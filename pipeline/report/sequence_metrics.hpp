// report/sequence_metrics.hpp: error measures over a sequence of frames: temporal error (flicker
// against the reference's own change), lag after a change, and the interpolation that finds the
// accumulation spp matching a given error.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace asvgf::report {

// Temporal error of frame t: mean over pixels and RGB of
//   ((m_t - m_{t-1}) - (r_t - r_{t-1}))^2 / (r_t^2 + 0.01)
// i.e. relMSE of the method's frame-to-frame change against the reference's change, normalised by
// the reference's brightness as relMSE is (the same 0.01 guard). Images are RGBA floats.
double temporal_error(std::span<const float> method, std::span<const float> method_previous,
                      std::span<const float> reference, std::span<const float> reference_previous);

// Frames where the scene changes: [first, last] are the frames whose state differs from the frame
// before. `changed[t]` is true when frame t differs from t-1 (changed[0] is ignored).
struct ChangeWindow {
  int first = 0, last = 0;
};
std::optional<ChangeWindow> find_change(const std::vector<bool>& changed);

// Lag after the change that starts at frame c: threshold = 2 x the mean error of frames [1, c)
// (frame 0 has no history and is left out; with c <= 1 there is nothing to measure). The lag is
// t - c for the first frame t >= c from which the error stays at or under the threshold to the end
// of the sequence; empty when the last frame is still above it ("more than frames - c").
struct Lag {
  bool measured = false;
  std::string why_not;  // when !measured
  int change_frame = 0;
  double steady_error = 0, threshold = 0;
  std::optional<int> frames;
  double peak_error = 0;  // worst error at or after the change
  // How near the threshold the frames that decide the lag came, as error / threshold: the largest
  // from the lag's end on (under 1), and the last frame over it (where the lag is not 0). A ratio
  // near 1 means a change of that size in one frame's error moves the lag.
  std::optional<double> settled_ratio, last_over_ratio;
};
Lag measure_lag(const std::vector<double>& error, std::optional<ChangeWindow> change);

// Given points (x_i, y_i) with x increasing and y mostly decreasing (accumulation: spp -> relMSE),
// the x at which y reaches `target`, interpolated linearly in log x / log y between the two points
// that bracket it. Empty when `target` is outside the curve's range (below its lowest error: more
// than the largest x; above its highest: less than the smallest).
struct CurveHit {
  std::optional<double> x;
  bool below_range = false;  // target is lower than every y: x > last x
  bool above_range = false;  // target is higher than every y: x < first x
};
CurveHit interpolate_loglog(const std::vector<double>& xs, const std::vector<double>& ys, double target);
// y at x on the same log-log polyline (extrapolated linearly in log-log from the nearest segment).
double evaluate_loglog(const std::vector<double>& xs, const std::vector<double>& ys, double x);

// Energy bias of a run: the sum of its mean linear radiance over the frames where its temporal
// history is saturated, against the reference's sum over the same frames, minus 1 (0.01 = 1% too
// bright). A frame counts when it is at least `ramp` frames after frame 0 and after the last frame
// of the change (a history blends uniformly, 1/n, until n reaches 1/alpha; `ramp` = 0 for methods
// without a history) and its reference is not black. Empty when no frame counts.
struct EnergyBias {
  std::optional<double> bias;
  int frames = 0;  // frames that counted
};
EnergyBias energy_bias(const std::vector<double>& mean, const std::vector<double>& reference_mean,
                       std::optional<ChangeWindow> change, int ramp);

double mean(const std::vector<double>& v);  // of the finite values; NaN when none
double median(std::vector<double> v);       // of the finite values; NaN when none

}  // namespace asvgf::report
