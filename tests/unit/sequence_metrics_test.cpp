// report/sequence_metrics: the energy bias counts exactly the frames with a saturated history and
// a lit reference; the lag counts the frames until the error stays under its threshold, and says
// how near the deciding frames came to it.
#include <doctest/doctest.h>

#include "report/sequence_metrics.hpp"

using namespace asvgf::report;

TEST_CASE("energy bias: sums over frames with a saturated history and a lit reference, against the reference") {
  // Frames 0..9; the change spans frames 4..5; ramp 2: frames 2, 3 and 7, 8, 9 count.
  const std::vector<double> reference = {1, 1, 1, 1, 5, 5, 2, 2, 2, 2};
  std::vector<double> method = {9, 9, 0.9, 0.9, 9, 9, 9, 1.8, 1.8, 1.8};
  const ChangeWindow change{4, 5};
  const EnergyBias e = energy_bias(method, reference, change, 2);
  REQUIRE(e.bias.has_value());
  CHECK(e.frames == 5);
  CHECK(*e.bias == doctest::Approx((0.9 * 2 + 1.8 * 3) / (1.0 * 2 + 2.0 * 3) - 1.0));
  CHECK(*e.bias == doctest::Approx(-0.1));

  SUBCASE("no history (ramp 0) and no change: every frame counts") {
    const EnergyBias all = energy_bias(method, reference, std::nullopt, 0);
    CHECK(all.frames == 10);
  }
  SUBCASE("a black reference never counts, and no frame gives no number") {
    const std::vector<double> black(10, 0.0);
    const EnergyBias none = energy_bias(method, black, change, 2);
    CHECK(none.frames == 0);
    CHECK_FALSE(none.bias.has_value());
  }
  SUBCASE("a ramp longer than the run gives no number") {
    CHECK_FALSE(energy_bias(method, reference, change, 20).bias);
  }
}

// The lag (report.md's definitions) and how near its deciding frames came to the threshold: on
// light-exit at 1080p a 1.3% change in one frame's error moved it between 0 and 2 frames
// (docs/performance.md, "13 taps: the lag over three seeds"), which the ratios make visible.
TEST_CASE("lag: frames from the change until the error stays under twice its steady value, with the margins") {
  // Steady error 1 over frames 1..3 (frame 0 has no history): threshold 2. The change starts at 4.
  const ChangeWindow change{4, 6};
  std::vector<double> error = {9, 1, 1, 1, 1.9, 2.04, 0.5, 0.2};
  Lag lag = measure_lag(error, change);
  REQUIRE(lag.measured);
  CHECK(lag.change_frame == 4);
  CHECK(lag.steady_error == doctest::Approx(1.0));
  CHECK(lag.threshold == doctest::Approx(2.0));
  REQUIRE(lag.frames.has_value());
  CHECK(*lag.frames == 2);  // frame 5 is over: back under from frame 6
  CHECK(lag.peak_error == doctest::Approx(2.04));
  REQUIRE(lag.last_over_ratio.has_value());
  CHECK(*lag.last_over_ratio == doctest::Approx(1.02));
  REQUIRE(lag.settled_ratio.has_value());
  CHECK(*lag.settled_ratio == doctest::Approx(0.25));

  SUBCASE("the same frame 2% lower: lag 0, and the margin says how near it came") {
    error[5] = 1.998;
    lag = measure_lag(error, change);
    REQUIRE(lag.frames.has_value());
    CHECK(*lag.frames == 0);
    CHECK_FALSE(lag.last_over_ratio.has_value());
    REQUIRE(lag.settled_ratio.has_value());
    CHECK(*lag.settled_ratio == doctest::Approx(0.999));
  }
  SUBCASE("still over at the last frame: no lag in frames, and no frame settled") {
    error.back() = 3.0;
    lag = measure_lag(error, change);
    CHECK_FALSE(lag.frames.has_value());
    CHECK_FALSE(lag.settled_ratio.has_value());
    REQUIRE(lag.last_over_ratio.has_value());
    CHECK(*lag.last_over_ratio == doctest::Approx(1.5));
  }
  SUBCASE("nothing changes, or no frame with history before the change: not measured") {
    CHECK_FALSE(measure_lag(error, std::nullopt).measured);
    CHECK_FALSE(measure_lag(error, ChangeWindow{1, 2}).measured);
  }
}
