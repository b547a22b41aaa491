// report/text.hpp: how the report writes its numbers (report.md and the cross-scene summary).
#pragma once

#include <string>

#include "report/sequence_metrics.hpp"

namespace asvgf::report {

// `digits` significant digits; "–" for NaN and infinities (a measure that does not apply).
std::string number_text(double v, int digits = 3);
// "-3.2% (14 frames)", or "n/a" when no frame had a saturated history and a lit reference.
std::string energy_text(const EnergyBias& e);
// Frames until the error is back under its threshold; "> N" when it never is; "n/a" unmeasured.
std::string lag_text(const Lag& lag, int frames);
// How near the threshold the deciding frames came: "frames after it at most 0.995x the threshold, the
// last over it 1.016x" (either part where it applies); empty when unmeasured.
std::string lag_margin_text(const Lag& lag);

}  // namespace asvgf::report
