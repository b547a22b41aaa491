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

struct GraphOptions {
  std::string scene = "cornell";
  std::string animation = "light-exit";
  std::string method = "asvgf";
  std::string size = "128x128";
  int frame = 1;
  int atrous_iterations = 5;
  bool specular_split = false;
  std::string dot;
};

int run_graph(const GraphOptions& o) {
  frame::FrameSettings settings;
  settings.method = *frame::method_from_string(o.method);  // validated by the CLI
  const ImageSize size = parse_size_option("--size", o.size);
  settings.width = size.width;
  settings.height = size.height;
  settings.denoise.atrous_iterations = o.atrous_iterations;
  settings.specular_split = o.specular_split;

  const auto owned = hal::validate::wrap(std::make_unique<hal::record::RecordDevice>());
  hal::Device& device = *owned;
  const scene::Scene scene = scene::builtin_scene(o.scene, o.animation);
  render::SceneGpu scene_gpu(device, scene, device.capabilities().ray_query);
  const auto usage = hal::ImageUsage::Storage | hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc;
  frame::FrameTargets targets{
      device.create_image({"hdr", settings.width, settings.height, hal::Format::RGBA32F, usage}),
      hal::State::Undefined,
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
      std::printf("scene %s, animation %s, method %s, %ux%u\n%s", o.scene.c_str(), o.animation.c_str(),
                  o.method.c_str(), settings.width, settings.height, compiled.text().c_str());
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
  cmd->add_option("--scene", options->scene, "Built-in scene")
      ->check(CLI::IsMember(scene::builtin_scenes()))
      ->capture_default_str();
  cmd->add_option("--animation", options->animation, "Animation of the built-in scene")
      ->check(CLI::IsMember(scene::builtin_animations()))
      ->capture_default_str();
  cmd->add_option("--method", options->method, "Denoising method")
      ->check(CLI::IsMember({"raw", "ema", "svgf", "asvgf", "reference"}))
      ->capture_default_str();
  cmd->add_option("--size", options->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--frame", options->frame, "Frame to print (frame 0 has no history yet)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_option("--atrous-iterations", options->atrous_iterations, "A-trous iterations (svgf, asvgf)")
      ->check(CLI::Range(0, 16))
      ->capture_default_str();
  cmd->add_flag("--specular-split", options->specular_split,
                "On glossy scenes, diffuse and specular light in chains of their own");
  cmd->add_option("--dot", options->dot, "Also write the graph as Graphviz to this file");
  return [options] { return run_graph(*options); };
}

}  // namespace asvgf::cli
