// `asvgf bench`: GPU time per pass and rays per second of the frame, from timestamps, after warm-up
// frames; medians over the measured frames. On a CPU device (lavapipe) the "GPU" times are the
// CPU's, which the output says.
#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

#include "commands.hpp"
#include "scene_options.hpp"

namespace asvgf::cli {
namespace {

struct BenchOptions {
  SceneOptions scene;
  int warmup = 2;
  int frames = 5;
  int first_frame = 4;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

int run_bench(BenchOptions& o) {
  finish_scene_options(o.scene);
  const scene::Scene scene = load_scene(o.scene);
  auto device = open_device(o.scene);
  render::RenderSettings settings = render_settings(o.scene);
  render::Renderer renderer(*device, scene, settings);
  const bool cpu = device->adapter().type == hal::DeviceType::Cpu;
  std::printf("device:   %s%s\n", device->adapter().name.c_str(), cpu ? " (a CPU: times are not GPU times)" : "");
  std::printf("tracing:  %s\n", renderer.ray_query() ? "ray queries" : "software BVH");
  std::printf("frame:    %s, %s, %ux%u, %d warm-up + %d measured frames from frame %d\n", scene.name.c_str(),
              o.scene.method.c_str(), settings.width, settings.height, o.warmup, o.frames, o.first_frame);
  std::map<std::string, std::vector<double>> pass_ms;
  std::vector<std::string> order;
  std::vector<double> frame_ms, rays_per_s, trace_ms;
  for (int i = 0; i < o.warmup + o.frames; ++i) {
    renderer.render(o.first_frame + i);
    if (i < o.warmup) continue;
    double total = 0.0, tracing = 0.0;
    for (const auto& t : renderer.timings()) {
      if (!t.gpu_ms) {
        std::fprintf(stderr, "asvgf bench: the device has no timestamps; nothing to measure\n");
        return 1;
      }
      if (!pass_ms.count(t.pass)) order.push_back(t.pass);
      pass_ms[t.pass].push_back(*t.gpu_ms);
      total += *t.gpu_ms;
      if (t.pass == "gbuffer" || t.pass == "pathtrace") tracing += *t.gpu_ms;
    }
    frame_ms.push_back(total);
    trace_ms.push_back(tracing);
    rays_per_s.push_back(tracing > 0 ? double(renderer.rays_last_frame()) / (tracing * 1e-3) : 0.0);
  }
  std::printf("\n%-22s %10s\n", "pass", "ms (median)");
  for (const auto& p : order) std::printf("%-22s %10.3f\n", p.c_str(), median(pass_ms[p]));
  std::printf("%-22s %10.3f\n", "frame", median(frame_ms));
  std::printf("\nrays per frame:        %llu (primary + path continuation + shadow)\n",
              static_cast<unsigned long long>(renderer.rays_last_frame()));
  std::printf("tracing time:          %.3f ms (gbuffer + pathtrace)\n", median(trace_ms));
  std::printf("rays per second:       %.2f M\n", median(rays_per_s) * 1e-6);
  return 0;
}

}  // namespace

std::function<int()> add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("bench", "Measure GPU time per pass and rays per second");
  add_scene_options(*cmd, o->scene);
  cmd->add_option("--warmup", o->warmup, "Frames rendered before measuring")->check(CLI::Range(0, 100))->capture_default_str();
  cmd->add_option("--frames", o->frames, "Frames measured")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_option("--first-frame", o->first_frame, "Animation frame to start at")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  return [o] { return run_bench(*o); };
}

}  // namespace asvgf::cli
