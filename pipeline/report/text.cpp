#include "report/text.hpp"

#include <cmath>
#include <cstdio>

namespace asvgf::report {

std::string number_text(double v, int digits) {
  if (!std::isfinite(v)) return "–";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string energy_text(const EnergyBias& e) {
  if (!e.bias) return "n/a";
  char text[64];
  std::snprintf(text, sizeof text, "%+.2f%% (%d frames)", 100.0 * *e.bias, e.frames);
  return text;
}

std::string lag_text(const Lag& lag, int frames) {
  if (!lag.measured) return "n/a";
  if (!lag.frames) return "> " + std::to_string(frames - 1 - lag.change_frame);
  return std::to_string(*lag.frames);
}

std::string lag_margin_text(const Lag& lag) {
  if (!lag.measured) return "";
  char text[96];
  std::string out;
  if (lag.settled_ratio) {
    std::snprintf(text, sizeof text, "frames after it at most %.3fx the threshold", *lag.settled_ratio);
    out = text;
  }
  if (lag.last_over_ratio) {
    std::snprintf(text, sizeof text, "the last over it %.3fx", *lag.last_over_ratio);
    out += (out.empty() ? "" : ", ") + std::string(text);
  }
  return out;
}

}  // namespace asvgf::report
