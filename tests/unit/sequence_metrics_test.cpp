// report/sequence_metrics: the energy bias counts exactly the frames with a saturated history and
// a lit reference.
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
