// The valid range of every denoiser setting (include/asvgf/denoise_settings.hpp), checked in one
// place for the API, the renderer and the command line alike.
#include "asvgf/denoise_settings.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace asvgf {
namespace {

struct Rule {
  SettingRange range;
  std::function<bool(const DenoiseSettings&)> valid;
  std::function<std::string(const DenoiseSettings&)> value;
};

std::string text(float v) {
  std::ostringstream s;
  s << v;  // "nan", "inf", "-inf" as printf writes them
  return s.str();
}

bool in_open_closed(float v, float lo, float hi) {
  return v > lo && v <= hi;
}  // false for NaN
bool in_closed(float v, float lo, float hi) {
  return v >= lo && v <= hi;
}
bool positive_finite(float v) {
  return v > 0.0f && std::isfinite(v);
}
bool non_negative_finite(float v) {
  return v >= 0.0f && std::isfinite(v);
}

// Member name, option, range text, test and printed value for each setting. The ranges are what
// the shaders are written for: iteration counts bound loops and history images, sigmas divide
// (0 or infinity gives NaN weights), blend factors outside (0, 1] grow or freeze the histories.
const std::vector<Rule>& rules() {
  static const std::vector<Rule> all = {
      {{"alpha", "--alpha", "(0, 1]"},
       [](const auto& s) { return in_open_closed(s.alpha, 0, 1); },
       [](const auto& s) { return text(s.alpha); }},
      {{"moments_alpha", "--moments-alpha", "(0, 1]"},
       [](const auto& s) { return in_open_closed(s.moments_alpha, 0, 1); },
       [](const auto& s) { return text(s.moments_alpha); }},
      {{"atrous_iterations", "--atrous-iterations", "0..16"},
       [](const auto& s) { return s.atrous_iterations >= 0 && s.atrous_iterations <= 16; },
       [](const auto& s) { return std::to_string(s.atrous_iterations); }},
      {{"sigma_z", "--sigma-z", "(0, inf), finite"},
       [](const auto& s) { return positive_finite(s.sigma_z); },
       [](const auto& s) { return text(s.sigma_z); }},
      {{"sigma_n", "--sigma-n", "[0, inf), finite"},
       [](const auto& s) { return non_negative_finite(s.sigma_n); },
       [](const auto& s) { return text(s.sigma_n); }},
      {{"sigma_l", "--sigma-l", "[0, inf), finite (0: by the image's size)"},
       [](const auto& s) { return non_negative_finite(s.sigma_l); },
       [](const auto& s) { return text(s.sigma_l); }},
      {{"kernel", "--kernel", "b3spline or box"},
       [](const auto& s) { return s.kernel == AtrousKernel::B3Spline || s.kernel == AtrousKernel::Box; },
       [](const auto& s) { return std::to_string(static_cast<std::uint32_t>(s.kernel)); }},
      {{"gradient_iterations", "--gradient-iterations", "0..8"},
       [](const auto& s) { return s.gradient_iterations >= 0 && s.gradient_iterations <= 8; },
       [](const auto& s) { return std::to_string(s.gradient_iterations); }},
      {{"history_cap", "--history-cap", "[1, 4096]"},
       [](const auto& s) { return in_closed(s.history_cap, 1, 4096); },
       [](const auto& s) { return text(s.history_cap); }},
      {{"history_tap", "--history-tap", "-1..atrous_iterations-1 (-1 or 0 without a-trous iterations)"},
       [](const auto& s) { return s.history_tap >= -1 && s.history_tap < std::max(1, s.atrous_iterations); },
       [](const auto& s) { return std::to_string(s.history_tap); }},
      {{"gradient_source", "--gradient-source", "reshaded or reprojected"},
       [](const auto& s) {
         return s.gradient_source == GradientSource::Reshaded || s.gradient_source == GradientSource::Reprojected;
       },
       [](const auto& s) { return std::to_string(static_cast<std::uint32_t>(s.gradient_source)); }},
      {{"antilag", "--antilag", "[0, 64]"},
       [](const auto& s) { return in_closed(s.antilag, 0, 64); },
       [](const auto& s) { return text(s.antilag); }},
      {{"min_history", "", "[0, 4096]"},
       [](const auto& s) { return in_closed(s.min_history, 0, 4096); },
       [](const auto& s) { return text(s.min_history); }},
      {{"exposure", "", "[0, inf), finite"},
       [](const auto& s) { return non_negative_finite(s.exposure); },
       [](const auto& s) { return text(s.exposure); }},
      {{"tonemap", "", "clamp or aces"},
       [](const auto& s) { return s.tonemap == Tonemap::Clamp || s.tonemap == Tonemap::Aces; },
       [](const auto& s) { return std::to_string(static_cast<std::uint32_t>(s.tonemap)); }},
      {{"specular_atrous_iterations", "--specular-atrous-iterations", "0..16"},
       [](const auto& s) { return s.specular_atrous_iterations >= 0 && s.specular_atrous_iterations <= 16; },
       [](const auto& s) { return std::to_string(s.specular_atrous_iterations); }},
      {{"specular_sigma_l", "--specular-sigma-l", "[0, inf), finite (0: sigma_l's)"},
       [](const auto& s) { return non_negative_finite(s.specular_sigma_l); },
       [](const auto& s) { return text(s.specular_sigma_l); }},
      {{"specular_alpha", "--specular-alpha", "[0, 1] (0: alpha's)"},
       [](const auto& s) { return in_closed(s.specular_alpha, 0, 1); },
       [](const auto& s) { return text(s.specular_alpha); }},
      {{"local_mean", "--local-mean", "-1 (by the image's size), 0 (off) or odd 3..255"},
       [](const auto& s) {
         return s.local_mean == -1 || s.local_mean == 0 ||
                (s.local_mean >= 3 && s.local_mean <= 255 && s.local_mean % 2 == 1);
       },
       [](const auto& s) { return std::to_string(s.local_mean); }},
  };
  return all;
}

}  // namespace

const std::vector<SettingRange>& setting_ranges() {
  static const std::vector<SettingRange> all = [] {
    std::vector<SettingRange> r;
    for (const auto& rule : rules()) r.push_back(rule.range);
    return r;
  }();
  return all;
}

std::string_view setting_range(std::string_view setting) {
  for (const auto& r : setting_ranges())
    if (setting == r.setting) return r.range;
  return {};
}

float luminance_sigma(const DenoiseSettings& settings, std::uint32_t width, std::uint32_t height) {
  if (settings.sigma_l > 0.0f) return settings.sigma_l;
  const double side = std::sqrt(double(width) * double(height));
  return float(4.0 * std::clamp(side / 256.0, 1.0, 3.0));
}

int local_mean_window(const DenoiseSettings& settings, std::uint32_t width, std::uint32_t height) {
  if (settings.local_mean >= 0) return settings.local_mean;
  const std::uint32_t sixteenth = (std::min(width, height) + 8) / 16;
  return static_cast<int>(std::clamp(sixteenth | 1u, 5u, 255u));
}

std::string SettingProblem::message() const {
  const std::string option = *setting.option ? std::string(" (") + setting.option + ")" : "";
  return std::string(setting.setting) + option + " is " + value + ", valid: " + setting.range;
}

std::optional<SettingProblem> check_settings(const DenoiseSettings& settings) {
  for (const auto& rule : rules())
    if (!rule.valid(settings)) return SettingProblem{rule.range, rule.value(settings)};
  return std::nullopt;
}

}  // namespace asvgf
