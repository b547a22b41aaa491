// The one check of the denoiser's settings (asvgf::check_settings): every setting refuses NaN,
// infinities and values outside its range, naming the setting, its option and the range; the
// defaults and the range ends pass.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <string>

#include "asvgf/denoise_settings.hpp"
#include "denoiser/passes/local_mean.hpp"

using namespace asvgf;

namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

struct Case {
  const char* setting;
  std::function<void(DenoiseSettings&)> set;
};

}  // namespace

TEST_CASE("denoiser settings: the defaults and every range's ends pass the check") {
  CHECK_FALSE(check_settings(DenoiseSettings{}).has_value());
  const Case good[] = {
      {"alpha", [](auto& s) { s.alpha = 1.0f; }},
      {"alpha", [](auto& s) { s.alpha = 1e-6f; }},
      {"moments_alpha", [](auto& s) { s.moments_alpha = 1.0f; }},
      {"atrous_iterations", [](auto& s) { s.atrous_iterations = 0, s.history_tap = 0; }},
      {"atrous_iterations", [](auto& s) { s.atrous_iterations = 16; }},
      {"sigma_n", [](auto& s) { s.sigma_n = 0.0f; }},
      {"sigma_l", [](auto& s) { s.sigma_l = 0.0f; }},
      {"sigma_l", [](auto& s) { s.sigma_l = 1e-6f; }},
      {"gradient_iterations", [](auto& s) { s.gradient_iterations = 8; }},
      {"history_cap", [](auto& s) { s.history_cap = 1.0f; }},
      {"history_cap", [](auto& s) { s.history_cap = 4096.0f; }},
      {"history_tap", [](auto& s) { s.history_tap = s.atrous_iterations - 1; }},
      {"history_tap", [](auto& s) { s.history_tap = -1; }},
      {"history_tap", [](auto& s) { s.atrous_iterations = 0, s.history_tap = -1; }},
      {"antilag", [](auto& s) { s.antilag = 0.0f; }},
      {"antilag", [](auto& s) { s.antilag = 64.0f; }},
      {"min_history", [](auto& s) { s.min_history = 0.0f; }},
      {"exposure", [](auto& s) { s.exposure = 0.0f; }},
      {"specular_atrous_iterations", [](auto& s) { s.specular_atrous_iterations = 0; }},
      {"specular_sigma_l", [](auto& s) { s.specular_sigma_l = 32.0f; }},
      {"specular_alpha", [](auto& s) { s.specular_alpha = 1.0f; }},
      {"local_mean", [](auto& s) { s.local_mean = 0; }},
      {"local_mean", [](auto& s) { s.local_mean = 3; }},
      {"local_mean", [](auto& s) { s.local_mean = 255; }},
  };
  for (const auto& c : good) {
    DenoiseSettings s;
    c.set(s);
    CAPTURE(c.setting);
    const auto problem = check_settings(s);
    CHECK_MESSAGE(!problem, (problem ? problem->message() : std::string()));
  }
}

TEST_CASE(
    "denoiser settings: NaN, infinities and out-of-range values are refused naming the setting, option and range") {
  const Case bad[] = {
      {"alpha", [](auto& s) { s.alpha = kNan; }},
      {"alpha", [](auto& s) { s.alpha = 0.0f; }},
      {"alpha", [](auto& s) { s.alpha = 1.5f; }},
      {"moments_alpha", [](auto& s) { s.moments_alpha = kNan; }},
      {"moments_alpha", [](auto& s) { s.moments_alpha = -0.1f; }},
      {"atrous_iterations", [](auto& s) { s.atrous_iterations = -1; }},
      {"atrous_iterations", [](auto& s) { s.atrous_iterations = 17; }},
      {"sigma_z", [](auto& s) { s.sigma_z = 0.0f; }},
      {"sigma_z", [](auto& s) { s.sigma_z = kInf; }},
      {"sigma_z", [](auto& s) { s.sigma_z = kNan; }},
      {"sigma_n", [](auto& s) { s.sigma_n = -1.0f; }},
      {"sigma_n", [](auto& s) { s.sigma_n = kNan; }},
      {"sigma_n", [](auto& s) { s.sigma_n = kInf; }},
      {"sigma_l", [](auto& s) { s.sigma_l = -1.0f; }},
      {"sigma_l", [](auto& s) { s.sigma_l = kNan; }},
      {"sigma_l", [](auto& s) { s.sigma_l = kInf; }},
      {"kernel", [](auto& s) { s.kernel = static_cast<AtrousKernel>(7); }},
      {"gradient_iterations", [](auto& s) { s.gradient_iterations = 9; }},
      {"gradient_iterations", [](auto& s) { s.gradient_iterations = -1; }},
      {"history_cap", [](auto& s) { s.history_cap = kNan; }},
      {"history_cap", [](auto& s) { s.history_cap = 0.5f; }},
      {"history_cap", [](auto& s) { s.history_cap = kInf; }},
      {"history_tap", [](auto& s) { s.history_tap = s.atrous_iterations; }},
      {"history_tap", [](auto& s) { s.history_tap = -2; }},
      {"history_tap", [](auto& s) { s.atrous_iterations = 0, s.history_tap = 1; }},
      {"gradient_source", [](auto& s) { s.gradient_source = static_cast<GradientSource>(2); }},
      {"antilag", [](auto& s) { s.antilag = kNan; }},
      {"antilag", [](auto& s) { s.antilag = -1.0f; }},
      {"antilag", [](auto& s) { s.antilag = 65.0f; }},
      {"min_history", [](auto& s) { s.min_history = kNan; }},
      {"min_history", [](auto& s) { s.min_history = -1.0f; }},
      {"exposure", [](auto& s) { s.exposure = kInf; }},
      {"exposure", [](auto& s) { s.exposure = -1.0f; }},
      {"tonemap", [](auto& s) { s.tonemap = static_cast<Tonemap>(5); }},
      {"specular_atrous_iterations", [](auto& s) { s.specular_atrous_iterations = 17; }},
      {"specular_sigma_l", [](auto& s) { s.specular_sigma_l = -1.0f; }},
      {"specular_sigma_l", [](auto& s) { s.specular_sigma_l = kNan; }},
      {"specular_sigma_l", [](auto& s) { s.specular_sigma_l = kInf; }},
      {"specular_alpha", [](auto& s) { s.specular_alpha = -0.1f; }},
      {"specular_alpha", [](auto& s) { s.specular_alpha = 1.5f; }},
      {"specular_alpha", [](auto& s) { s.specular_alpha = kNan; }},
      {"local_mean", [](auto& s) { s.local_mean = 1; }},
      {"local_mean", [](auto& s) { s.local_mean = 4; }},
      {"local_mean", [](auto& s) { s.local_mean = 257; }},
      {"local_mean", [](auto& s) { s.local_mean = -5; }},
      {"local_mean", [](auto& s) { s.local_mean = -2; }},
  };
  for (const auto& c : bad) {
    DenoiseSettings s;
    c.set(s);
    CAPTURE(c.setting);
    const auto problem = check_settings(s);
    REQUIRE(problem.has_value());
    CHECK(std::string(problem->setting.setting) == c.setting);
    const std::string m = problem->message();
    CHECK(m.find(c.setting) != std::string::npos);
    CHECK(m.find(setting_range(c.setting)) != std::string::npos);
    CHECK(m.find(problem->setting.option) != std::string::npos);
  }
}

TEST_CASE("denoiser settings: every checked setting has a range, and every range names a DenoiseSettings member once") {
  std::set<std::string> names;
  for (const auto& r : setting_ranges()) {
    CHECK(names.insert(r.setting).second);
    CHECK(std::string(r.range).size() > 0);
  }
  // Every member of DenoiseSettings.
  for (const char* member :
       {"alpha", "moments_alpha", "atrous_iterations", "sigma_z", "sigma_n", "sigma_l", "kernel", "gradient_iterations",
        "history_cap", "history_tap", "gradient_source", "antilag", "min_history", "exposure", "tonemap",
        "specular_atrous_iterations", "specular_sigma_l", "specular_alpha", "local_mean"})
    CHECK_MESSAGE(names.count(member) == 1, member << " has no range");
}

TEST_CASE("luminance_sigma: a set sigma_l wins, 0 gives 4 up to 256x256, 12 from 768x768, between them with the size") {
  DenoiseSettings s;
  REQUIRE(s.sigma_l == 0.0f);  // the default is the size's
  CHECK(luminance_sigma(s, 1, 1) == 4.0f);
  CHECK(luminance_sigma(s, 64, 64) == 4.0f);
  CHECK(luminance_sigma(s, 256, 256) == 4.0f);
  CHECK(luminance_sigma(s, 384, 384) == doctest::Approx(6.0f));
  CHECK(luminance_sigma(s, 512, 512) == 8.0f);
  CHECK(luminance_sigma(s, 768, 768) == 12.0f);
  CHECK(luminance_sigma(s, 1920, 1080) == 12.0f);
  CHECK(luminance_sigma(s, 16384, 16384) == 12.0f);
  CHECK(luminance_sigma(s, 1024, 256) == 8.0f);  // by the pixel count: sqrt(1024 x 256) = 512
  s.sigma_l = 3.0f;
  CHECK(luminance_sigma(s, 1920, 1080) == 3.0f);
  CHECK(luminance_sigma(s, 64, 64) == 3.0f);
}

TEST_CASE(
    "local_mean_window: a set window wins, 0 is off, -1 gives a sixteenth of the smaller side, odd, from 5 to 255") {
  DenoiseSettings s;
  REQUIRE(s.local_mean == -1);  // the default is the size's
  CHECK(local_mean_window(s, 1, 1) == 5);
  CHECK(local_mean_window(s, 48, 48) == 5);
  CHECK(local_mean_window(s, 64, 64) == 5);
  CHECK(local_mean_window(s, 128, 128) == 9);
  CHECK(local_mean_window(s, 256, 256) == 17);
  CHECK(local_mean_window(s, 1920, 256) == 17);  // by the smaller side
  CHECK(local_mean_window(s, 1280, 720) == 45);
  CHECK(local_mean_window(s, 1920, 1080) == 69);  // built as k 65 is: 9 blocks of 8, 72 pixels
  CHECK(passes::local_mean_blocks(69).block == passes::local_mean_blocks(65).block);
  CHECK(passes::local_mean_blocks(69).radius == passes::local_mean_blocks(65).radius);
  CHECK(local_mean_window(s, 3840, 2160) == 135);
  CHECK(local_mean_window(s, 16384, 16384) == 255);
  for (std::uint32_t side = 1; side <= 8192; ++side) {
    const int k = local_mean_window(s, side, side);
    CHECK((k % 2 == 1 && k >= 5 && k <= 255));
  }
  s.local_mean = 0;
  CHECK(local_mean_window(s, 1920, 1080) == 0);
  s.local_mean = 5;
  CHECK(local_mean_window(s, 1920, 1080) == 5);
}
