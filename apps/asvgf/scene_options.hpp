// Options shared by the commands that render: which scene, which device, how to render.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "renderer/renderer.hpp"
#include "renderer/scene/scene.hpp"

namespace asvgf::cli {

struct SceneOptions {
  std::string scene = "cornell";  // a built-in name or a scene file (.json)
  std::string animation = "light-exit";
  std::string method = "asvgf";
  std::string size = "128x128";
  std::uint32_t width = 128, height = 128;
  std::string backend;  // a name of hal_registry; empty: ASVGF_BACKEND, else the registry's default
  std::string device;   // Vulkan: index or name part; empty: ASVGF_DEVICE, then the best device
  bool software_bvh = false;
  bool validation = false;
  std::uint32_t seed = 0;
  std::uint32_t max_bounces = 4;
  asvgf::DenoiseSettings denoise;
  std::string kernel = "b3spline";
  std::string gradient_source = "reshaded";
  bool no_demodulation = false;  // --no-demodulation: filter radiance, albedo included
  bool specular_split = false;   // --specular-split: glossy scenes' diffuse and specular light filtered apart
};

// Registers --scene --animation --method --size --backend --device --software-bvh --validation
// --seed --max-bounces --no-demodulation and the denoiser parameters on `cmd`.
void add_scene_options(CLI::App& cmd, SceneOptions& options);
// The denoiser parameters alone (--alpha ... --history-tap, --kernel), part of add_scene_options.
void add_denoise_options(CLI::App& cmd, SceneOptions& options);
// --specular-split and the specular chain's settings (part of add_scene_options).
void add_specular_options(CLI::App& cmd, SceneOptions& options);
// --backend --device --validation (part of add_scene_options).
void add_device_options(CLI::App& cmd, SceneOptions& options);
// --backend alone (commands with their own scene options, e.g. report).
void add_backend_option(CLI::App& cmd, SceneOptions& options);
// Checks what CLI11 cannot (size syntax, the denoiser settings through asvgf::check_settings);
// throws CLI::ValidationError naming the option and its range (exit 2).
void finish_scene_options(SceneOptions& options);

struct ImageSize {
  std::uint32_t width = 0, height = 0;
};
constexpr std::uint32_t kMaxImageSide = 16384;
// The one WIDTHxHEIGHT parser: decimal digits only, both sides in 1..kMaxImageSide, nothing
// after the height (no wrap-around: 4294967297x1 is refused, not read as 1x1).
std::optional<ImageSize> parse_size(std::string_view text);
// parse_size, or CLI::ValidationError naming `option`.
ImageSize parse_size_option(const std::string& option, const std::string& text);
// --backend, else $ASVGF_BACKEND, else the registry's default backend. Throws CLI::ValidationError
// (exit 2) for an unknown ASVGF_BACKEND or a malformed variable the chosen backend reads.
std::string chosen_backend(const std::string& option);
// Whether that is the registry's default backend (commands leave it out of what they print).
bool default_backend_chosen(const std::string& option);
// Whether a --scene value names a scene file (.json) rather than a built-in scene.
bool is_scene_file(std::string_view scene);
// The scene the options name: built-in, or loaded from the file.
scene::Scene load_scene(const SceneOptions& options);
render::RenderSettings render_settings(const SceneOptions& options);
// The device of the chosen backend, behind the HAL validation layer. Throws hal::Error(NoDevice)
// naming the backend when it has none, CLI::ValidationError for an unknown ASVGF_BACKEND.
std::unique_ptr<hal::Device> open_device(const SceneOptions& options);
// What every app device goes through: the fault-injection layer when ASVGF_FAULT asks for it (a
// test hook, hal/fault.hpp; a malformed value is a CLI::ValidationError), then the validation layer.
std::unique_ptr<hal::Device> app_device(std::unique_ptr<hal::Device> backend);

}  // namespace asvgf::cli
