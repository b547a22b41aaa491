// `asvgf graph`: prints the compiled render graph of one frame (passes in order, barriers, passes
// left out and why, resource placement and memory), optionally as Graphviz. Runs on the
// recording HAL, so it needs no GPU; earlier frames are executed too, so histories exist.
#include <array>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

#include "asvgf/graph_runtime.hpp"
#include "commands.hpp"
#include "hal/validate.hpp"
#include "hal_record/record_device.hpp"
#include "io/atomic_file.hpp"
#include "renderer/frame_graph.hpp"
#include "renderer/scene/builtin.hpp"
#include "renderer/scene_gpu.hpp"
#include "scene_options.hpp"

namespace asvgf::cli {
namespace {

// The scene and the denoiser's settings are the rendering commands' (scene_options.hpp), checked
// the same way, so that the graph printed is the one `asvgf render` with those options runs.
struct GraphOptions {
  SceneOptions scene;
  int frame = 1;
  std::string dot;
};

int run_graph(GraphOptions& o) {
  finish_scene_options(o.scene);
  frame::FrameSettings settings;
  static_cast<frame::FrameConfig&>(settings) = render_settings(o.scene);

  const auto owned = hal::validate::wrap(std::make_unique<hal::record::RecordDevice>());
  hal::Device& device = *owned;
  const scene::Scene scene = load_scene(o.scene);
  render::SceneGpu scene_gpu(device, scene, device.capabilities().ray_query);
  const auto usage = hal::ImageUsage::Storage | hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc;
  const hal::Format hdr_format = frame::hdr_format(settings.method);
  frame::FrameTargets targets{
      device.create_image({"hdr", settings.width, settings.height, hdr_format, usage}),
      hal::State::Undefined,
      hdr_format,
      device.create_image({"display", settings.width, settings.height, hal::Format::RGBA8Unorm, usage}),
      hal::State::Undefined,
      {},
      hal::State::Undefined,
      device.create_buffer({"ray_counter", 16, hal::BufferUsage::Storage | hal::BufferUsage::CopyDst}),
      hal::State::Undefined};
  const std::array<std::byte, 16> zeros{};
  graph::GraphRuntime runtime(device);
  frame::FrameGraphBuilder builder(device);
  auto commands = device.create_command_list("frames");
  for (int f = 0;; ++f) {
    settings.scene_moved = scene_gpu.update(static_cast<float>(f)) && f > 0;
    settings.frame = static_cast<std::uint32_t>(f);
    device.upload_buffer(targets.ray_counter, 0, zeros);  // the path tracer counts into it
    targets.ray_counter_state = hal::State::CopyDst;
    auto g = builder.build(settings, scene_gpu, targets);
    auto compiled = runtime.compile(g);
    if (f == o.frame) {
      // A scene file has its own animation: --animation names a built-in scene's.
      const std::string animation = is_scene_file(o.scene.scene) ? "" : ", animation " + o.scene.animation;
      std::printf("scene %s%s, method %s, %ux%u\n%s", o.scene.scene.c_str(), animation.c_str(), o.scene.method.c_str(),
                  settings.width, settings.height, compiled.text().c_str());
      if (!o.dot.empty()) {
        render::write_file_atomic(o.dot, compiled.dot());
        std::printf("Graphviz written to %s\n", o.dot.c_str());
      }
      return 0;
    }
    runtime.execute(compiled, *commands);
    device.submit(*commands);
    device.wait();
    commands->reset();
    targets.hdr_state = targets.display_state = hal::State::CopySrc;
  }
}

}  // namespace

std::function<int()> add_graph_command(CLI::App& app) {
  auto options = std::make_shared<GraphOptions>();
  auto* cmd = app.add_subcommand("graph", "Print the compiled render graph of one frame (no GPU needed)");
  SceneOptions& o = options->scene;
  cmd->add_option("--scene", o.scene, "Built-in scene (cornell, glossy, textured, many) or a scene file (.json)")
      ->capture_default_str();
  cmd->add_option("--animation", o.animation, "Animation of the built-in scene")
      ->check(CLI::IsMember(scene::builtin_animations()))
      ->capture_default_str();
  cmd->add_option("--method", o.method, "Denoising method")
      ->check(CLI::IsMember({"raw", "ema", "svgf", "asvgf", "reference"}))
      ->capture_default_str();
  cmd->add_option("--size", o.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--frame", options->frame, "Frame to print (frame 0 has no history yet)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_flag("--no-demodulation", o.no_demodulation, "Denoise radiance with the albedo in it");
  add_specular_options(*cmd, o);
  add_denoise_options(*cmd, o);
  cmd->add_option("--dot", options->dot, "Also write the graph as Graphviz to this file");
  return [options] { return run_graph(*options); };
}

}  // namespace asvgf::cli
