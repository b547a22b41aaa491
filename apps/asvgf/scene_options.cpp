#include "scene_options.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string_view>

#include "hal/error.hpp"
#include "hal/fault.hpp"
#include "hal/validate.hpp"
#include "hal_registry/registry.hpp"
#include "renderer/scene/builtin.hpp"
#include "renderer/scene/scene_file.hpp"

namespace asvgf::cli {

namespace {

std::string backend_named(const std::string& option) {
  if (!option.empty()) return option;
  const char* env = std::getenv("ASVGF_BACKEND");
  if (!env || !*env) return hal::registry::default_backend().name;
  const std::string value = env;
  try {
    return hal::registry::backend(value).name;
  } catch (const hal::Error&) {
    throw CLI::ValidationError("ASVGF_BACKEND", "'" + value + "' is not one of " + hal::registry::names());
  }
}

}  // namespace

std::string chosen_backend(const std::string& option) {
  const std::string name = backend_named(option);
  // The chosen backend's own variables (ASVGF_GL_SHADERS) are bad input like ASVGF_BACKEND's.
  const auto& backend = hal::registry::backend(name);
  if (backend.environment_problem)
    if (const std::string problem = backend.environment_problem(); !problem.empty())
      throw CLI::ValidationError(problem);
  return name;
}

bool default_backend_chosen(const std::string& option) {
  return chosen_backend(option) == hal::registry::default_backend().name;
}

void add_backend_option(CLI::App& cmd, SceneOptions& o) {
  std::string help = "HAL backend:";
  std::vector<std::string> names;
  for (const auto& b : hal::registry::backends()) {
    help += (names.empty() ? " " : "; ") + b.name + " (" + b.description + ")";
    names.push_back(b.name);
  }
  help += " (default: $ASVGF_BACKEND, else " + hal::registry::default_backend().name + ")";
  cmd.add_option("--backend", o.backend, help)->check(CLI::IsMember(names));
}

void add_device_options(CLI::App& cmd, SceneOptions& o) {
  add_backend_option(cmd, o);
  cmd.add_option("--device", o.device, "Vulkan adapter: index or part of its name (default: $ASVGF_DEVICE, else best)");
  cmd.add_flag("--validation", o.validation, "Enable the Vulkan validation layer (synchronization validation on)");
}

namespace {
// A denoiser setting's option: its help ends with the library's range (asvgf::check_settings, run
// by finish_scene_options), so --help, the command line and the API refuse the same values.
template <typename T>
void add_setting_option(CLI::App& cmd, const char* option, T& value, const char* setting, const std::string& what) {
  cmd.add_option(option, value, what + "; " + std::string(setting_range(setting)))->capture_default_str();
}
}  // namespace

void add_scene_options(CLI::App& cmd, SceneOptions& o) {
  cmd.add_option("--scene", o.scene, "Built-in scene (cornell, glossy, textured, many) or a scene file (.json)")
      ->capture_default_str();
  cmd.add_option("--animation", o.animation, "Animation of the built-in scene")
      ->check(CLI::IsMember(scene::builtin_animations()))
      ->capture_default_str();
  cmd.add_option("--method", o.method, "raw, ema, svgf, asvgf or reference")
      ->check(CLI::IsMember({"raw", "ema", "svgf", "asvgf", "reference"}))
      ->capture_default_str();
  cmd.add_option("--size", o.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  add_device_options(cmd, o);
  cmd.add_flag("--software-bvh", o.software_bvh, "Trace with the software BVH even where ray queries exist");
  cmd.add_option("--seed", o.seed, "Random seed: the same seed gives the same images")->capture_default_str();
  cmd.add_option("--max-bounces", o.max_bounces, "Path length after the primary hit")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd.add_flag("--no-demodulation", o.no_demodulation,
               "Denoise radiance with the albedo in it instead of radiance / albedo (does the filter blur textures?)");
  add_specular_options(cmd, o);
  add_denoise_options(cmd, o);
}

void add_specular_options(CLI::App& cmd, SceneOptions& o) {
  cmd.add_flag("--specular-split", o.specular_split,
               "On glossy scenes, denoise diffuse and specular light apart, each with its own histories "
               "(ema, svgf, asvgf with the re-shaded gradient; not with --aovs)");
  add_setting_option(cmd, "--specular-atrous-iterations", o.denoise.specular_atrous_iterations,
                     "specular_atrous_iterations",
                     "A-trous iterations over the specular signal (--specular-split; Q2RTX 3)");
  add_setting_option(cmd, "--specular-sigma-l", o.denoise.specular_sigma_l, "specular_sigma_l",
                     "Luminance edge-stopping of the specular signal (--specular-split)");
  add_setting_option(cmd, "--specular-alpha", o.denoise.specular_alpha, "specular_alpha",
                     "Temporal blend factor of the specular signal (--specular-split)");
}

void add_denoise_options(CLI::App& cmd, SceneOptions& o) {
  auto& d = o.denoise;
  add_setting_option(cmd, "--alpha", d.alpha, "alpha", "Temporal blend factor (SVGF 0.2)");
  add_setting_option(cmd, "--moments-alpha", d.moments_alpha, "moments_alpha", "Moments blend factor (SVGF 0.2)");
  add_setting_option(cmd, "--atrous-iterations", d.atrous_iterations, "atrous_iterations",
                     "A-trous iterations (SVGF 5)");
  add_setting_option(cmd, "--sigma-z", d.sigma_z, "sigma_z", "Depth edge-stopping (SVGF 1)");
  add_setting_option(cmd, "--sigma-n", d.sigma_n, "sigma_n", "Normal edge-stopping exponent (SVGF 128)");
  add_setting_option(cmd, "--sigma-l", d.sigma_l, "sigma_l",
                     "Luminance edge-stopping (SVGF 4; 0: by the image's size, 4 up to 256x256, 12 from 768x768)");
  cmd.add_option("--kernel", o.kernel,
                 "A-trous kernel: b3spline (the paper's 5x5, its 13 taps with |i| + |j| <= 2) or box (3x3, seed)")
      ->check(CLI::IsMember({"b3spline", "box"}))
      ->capture_default_str();
  add_setting_option(cmd, "--gradient-iterations", d.gradient_iterations, "gradient_iterations",
                     "A-trous iterations over the gradient (Q2RTX 3)");
  cmd.add_option("--gradient-source", o.gradient_source,
                 "A-SVGF's gradient: reshaded (the renderer re-shades last frame's samples; paper) or reprojected "
                 "(estimated from reprojected noisy luminance, no renderer help; Q2RTX)")
      ->check(CLI::IsMember({"reshaded", "reprojected"}))
      ->capture_default_str();
  add_setting_option(cmd, "--antilag", d.antilag, "antilag",
                     "A-SVGF: how strongly the temporal gradient shortens the history (paper 1, measured best 8; 0: "
                     "constant alpha)");
  add_setting_option(cmd, "--history-cap", d.history_cap, "history_cap", "Maximum history length in frames");
  add_setting_option(
      cmd, "--history-tap", d.history_tap, "history_tap",
      "A-trous iteration whose output feeds the colour history (0: the first, SVGF; -1: none, the temporal "
      "result unfiltered)");
  add_setting_option(
      cmd, "--local-mean", d.local_mean, "local_mean",
      "Scale the filtered colour (and the colour history the a-trous tap feeds) toward the temporal "
      "result's local mean of luminance over about K x K pixels, giving back energy and contrast the a-trous filter "
      "loses (-1: by the image's size, a sixteenth of its smaller side, odd, from 5: 5 at 64x64, 17 at 256x256, 69 at "
      "1080p; 0: off, the paper's filter)");
}

std::optional<ImageSize> parse_size(std::string_view text) {
  auto number = [&](std::string_view digits) -> std::optional<std::uint32_t> {
    if (digits.empty() || digits.size() > 5) return std::nullopt;  // 16384 has 5 digits: no overflow
    std::uint32_t v = 0;
    for (const char c : digits) {
      if (c < '0' || c > '9') return std::nullopt;  // no sign, space or trailing text
      v = v * 10 + std::uint32_t(c - '0');
    }
    if (v == 0 || v > kMaxImageSide) return std::nullopt;
    return v;
  };
  const auto x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  const auto w = number(text.substr(0, x)), h = number(text.substr(x + 1));
  if (!w || !h) return std::nullopt;
  return ImageSize{*w, *h};
}

ImageSize parse_size_option(const std::string& option, const std::string& text) {
  const auto size = parse_size(text);
  if (!size)
    throw CLI::ValidationError(option,
                               "'" + text + "' is not WIDTHxHEIGHT with both in 1.." + std::to_string(kMaxImageSide));
  return *size;
}

void finish_scene_options(SceneOptions& o) {
  const ImageSize size = parse_size_option("--size", o.size);
  o.width = size.width;
  o.height = size.height;
  o.denoise.kernel = o.kernel == "box" ? asvgf::AtrousKernel::Box : asvgf::AtrousKernel::B3Spline;
  o.denoise.gradient_source =
      o.gradient_source == "reprojected" ? asvgf::GradientSource::Reprojected : asvgf::GradientSource::Reshaded;
  if (const auto problem = check_settings(o.denoise))
    throw CLI::ValidationError(*problem->setting.option ? problem->setting.option : problem->setting.setting,
                               problem->message());
}

bool is_scene_file(std::string_view scene) {
  return std::filesystem::path(scene).extension() == ".json";
}

scene::Scene load_scene(const SceneOptions& o) {
  if (is_scene_file(o.scene)) return scene::load_scene_file(o.scene);
  return scene::builtin_scene(o.scene, o.animation);
}

render::RenderSettings render_settings(const SceneOptions& o) {
  render::RenderSettings s;
  s.method = *frame::method_from_string(o.method);
  s.width = o.width;
  s.height = o.height;
  s.max_bounces = o.max_bounces;
  s.seed = o.seed;
  s.denoise = o.denoise;
  s.demodulate = !o.no_demodulation;
  s.specular_split = o.specular_split;
  if (o.software_bvh) s.ray_query = false;
  return s;
}

std::unique_ptr<hal::Device> app_device(std::unique_ptr<hal::Device> backend) {
  std::optional<hal::fault::EnvironmentPlan> faults;
  try {
    faults = hal::fault::from_environment();
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(e.what());
  }
  if (faults) backend = hal::fault::wrap(std::move(backend), faults->plan, faults->report_counts);
  return hal::validate::wrap(std::move(backend));
}

std::unique_ptr<hal::Device> open_device(const SceneOptions& o) {
  hal::registry::OpenOptions options;
  options.adapter = o.device;
  options.validation = o.validation;
  return app_device(hal::registry::backend(chosen_backend(o.backend)).open(options));
}

}  // namespace asvgf::cli
