// `asvgf bench`: GPU time per pass and rays per second of the frame, from timestamps, after warm-up
// frames; medians over the measured frames. Beside each pass: the bytes its declarations say it
// must read and write, the floor those bytes give at the bandwidth a buffer copy reaches on the
// same device (measured right after the frames), and the measured time over that floor. On a CPU
// device (lavapipe) the "GPU" times are the CPU's, which the output says.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "asvgf/pass_traffic.hpp"
#include "cache_latency.hpp"
#include "commands.hpp"
#include "copy_bandwidth.hpp"
#include "report/sequence_metrics.hpp"
#include "scene_options.hpp"

namespace asvgf::cli {
namespace {

struct BenchOptions {
  SceneOptions scene;
  int warmup = 2;
  int frames = 5;
  int first_frame = 4;
  int bandwidth_mib = 0;   // 0: 256 MiB on a GPU, 16 MiB on a CPU device
  float time_step = 1.0f;  // scene time per frame
  bool cache_latency = false;
  bool traffic = false;
};

// The passes that trace rays (pathtrace_carried: A-SVGF's re-shaded gradient samples, apart with
// split signals; otherwise inside pathtrace); every
// other pass of the frame is the denoiser's (the gradient chain and its sample selection
// included), which the denoiser line sums.
bool traces(const std::string& pass) {
  return pass == "gbuffer" || pass == "pathtrace" || pass == "pathtrace_carried";
}

struct Floor {
  std::uint64_t bytes = 0;
  bool counted = true;  // false: the pass also reads scene buffers of unknown size: the floor is low
};

using report::median;

// Each pass's declared resources and their bytes a pixel: what the B/pixel column is made of.
void print_traffic(const std::vector<graph::PassTraffic>& traffic, double pixels) {
  std::printf("\ntraffic (B/pixel of each declared resource: r read, w written, h last frame's version read):\n");
  for (const auto& t : traffic) {
    std::printf("%-22s %8.1f\n", t.pass.c_str(), double(t.read_bytes + t.written_bytes) / pixels);
    for (const auto& r : t.resources) {
      const char* use = r.history ? "h" : r.read && r.written ? "rw" : r.read ? "r" : "w";
      if (r.bytes == 0)
        std::printf("  %-30s %-2s %8s\n", r.name.c_str(), use, "?");
      else
        std::printf("  %-30s %-2s %8.1f\n", r.name.c_str(), use,
                    double(r.bytes) * (r.read && r.written ? 2 : 1) / pixels);
    }
  }
}

void print_cache_latency(hal::Device& device) {
  const auto rows = measure_cache_latency(device);
  if (rows.empty()) {
    std::printf("\ncache latency:         not measured (the device has no timestamps)\n");
    return;
  }
  std::printf("\ncache latency (ns a load, each load's address the last one's value; medians of 5 walks):\n");
  std::printf("%12s %16s %16s\n", "working set", "storage buffer", "sampled image");
  auto cell = [](const std::optional<double>& ns) {
    if (ns)
      std::printf(" %16.1f", *ns);
    else
      std::printf(" %16s", "-");
  };
  for (const auto& r : rows) {
    if (r.working_set >= (1u << 20))
      std::printf("%9llu MiB", static_cast<unsigned long long>(r.working_set >> 20));
    else
      std::printf("%9llu KiB", static_cast<unsigned long long>(r.working_set >> 10));
    cell(r.buffer_ns);
    cell(r.image_ns);
    std::printf("\n");
  }
  std::printf(
      "  (where the time steps up, a cache ends; a backend whose buffer column steps up earlier than its\n"
      "  image column, or than another backend's, gives its buffer loads less cache: hal/PORTING.md)\n");
}

int run_bench(BenchOptions& o) {
  finish_scene_options(o.scene);
  const scene::Scene scene = load_scene(o.scene);
  auto device = open_device(o.scene);
  render::RenderSettings settings = render_settings(o.scene);
  settings.read_back = false;  // nothing leaves the GPU: frames run back to back, as in a renderer
  settings.time_per_frame = o.time_step;
  render::Renderer renderer(*device, scene, settings);
  const bool cpu = device->adapter().type == hal::DeviceType::Cpu;
  std::printf("device:   %s%s\n", device->adapter().name.c_str(), cpu ? " (a CPU: times are not GPU times)" : "");
  std::printf("tracing:  %s\n", renderer.ray_query() ? "ray queries" : "software BVH");
  std::printf("frame:    %s, %s, %ux%u, %d warm-up + %d measured frames from frame %d, scene time %g a frame\n",
              scene.name.c_str(), o.scene.method.c_str(), settings.width, settings.height, o.warmup, o.frames,
              o.first_frame, o.time_step);
  std::map<std::string, std::vector<double>> pass_ms;
  std::vector<std::string> order;
  std::vector<double> frame_ms, rays_per_s, trace_ms;
  int moving = 0;
  // Render frame numbers whose scene time (frame x time step) starts at --first-frame.
  const int start = static_cast<int>(std::lround(o.first_frame / o.time_step));
  for (int i = 0; i < o.warmup + o.frames; ++i) {
    renderer.render(start + i);
    if (i < o.warmup) continue;
    moving += renderer.moved_last_frame();
    double total = 0.0, tracing = 0.0;
    for (const auto& t : renderer.timings()) {
      if (!t.gpu_ms) {
        std::fprintf(stderr, "asvgf bench: the device has no timestamps; nothing to measure\n");
        return 1;
      }
      if (!pass_ms.count(t.pass)) order.push_back(t.pass);
      pass_ms[t.pass].push_back(*t.gpu_ms);
      total += *t.gpu_ms;
      if (traces(t.pass)) tracing += *t.gpu_ms;
    }
    frame_ms.push_back(total);
    trace_ms.push_back(tracing);
    rays_per_s.push_back(tracing > 0 ? double(renderer.rays_last_frame()) / (tracing * 1e-3) : 0.0);
  }
  // The bytes of the last frame's passes; the measured frames all run the same passes.
  std::map<std::string, Floor> floors;
  const auto traffic = graph::pass_traffic(renderer.last_frame());
  for (const auto& t : traffic) floors[t.pass] = {t.read_bytes + t.written_bytes, !t.uncounted_reads};
  const std::uint64_t copy_bytes = std::uint64_t(o.bandwidth_mib > 0 ? o.bandwidth_mib : cpu ? 16 : 256) << 20;
  const auto bandwidth =
      measure_copy_bandwidth(*device, std::min(copy_bytes, device->capabilities().max_buffer_size), 20);
  const double per_ms = bandwidth ? bandwidth->bytes_per_second * 1e-3 : 0.0;  // bytes per millisecond

  const double pixels = double(settings.width) * double(settings.height);
  auto row = [&](const std::string& name, double ms, const Floor& f) {
    std::printf("%-22s %10.3f %10.2f %8.1f", name.c_str(), ms, double(f.bytes) / 1e6, double(f.bytes) / pixels);
    if (per_ms > 0 && f.bytes > 0)
      std::printf(" %10.4f %8.1f", double(f.bytes) / per_ms, ms / (double(f.bytes) / per_ms));
    else
      std::printf(" %10s %8s", "-", "-");
    std::printf("%s\n", f.counted ? "" : "  + scene reads");
  };
  std::printf("\n%-22s %10s %10s %8s %10s %8s\n", "pass", "ms", "MB moved", "B/pixel", "floor ms", "x floor");
  std::vector<double> denoiser_ms(frame_ms.size(), 0.0);
  Floor denoiser;
  for (const auto& p : order) {
    row(p, median(pass_ms[p]), floors[p]);
    if (traces(p)) continue;
    for (std::size_t f = 0; f < pass_ms[p].size() && f < denoiser_ms.size(); ++f) denoiser_ms[f] += pass_ms[p][f];
    denoiser.bytes += floors[p].bytes;
    denoiser.counted = denoiser.counted && floors[p].counted;
  }
  std::printf("%-22s %10.3f   (%d of %d measured frames moving%s)\n", "frame", median(frame_ms), moving, o.frames,
              moving < o.frames ? ": still frames skip the gradient passes; see --time-step" : "");
  row("denoiser", median(denoiser_ms), denoiser);
  std::printf(
      "  (ms: medians; denoiser: every pass but the tracing ones (gbuffer, pathtrace, pathtrace_carried),\n"
      "  summed per frame; MB moved: the\n"
      "  bytes each pass's declared images and buffers hold, read plus written, each once; B/pixel: the\n"
      "  same over the frame's pixels; + scene reads: the pass also traverses the scene, whose reads the\n"
      "  floor leaves out)\n");
  if (o.traffic) print_traffic(traffic, pixels);
  if (bandwidth)
    std::printf("\ncopy bandwidth:        %.3f TB/s (a %llu MiB buffer copy, read + written, median of 20: %.4f ms)\n",
                bandwidth->bytes_per_second * 1e-12, static_cast<unsigned long long>(bandwidth->bytes >> 20),
                bandwidth->median_ms);
  std::printf("\nrays per frame:        %llu (primary + path continuation + shadow)\n",
              static_cast<unsigned long long>(renderer.rays_last_frame()));
  std::printf("tracing time:          %.3f ms (gbuffer + pathtrace + pathtrace_carried)\n", median(trace_ms));
  std::printf("rays per second:       %.2f M\n", median(rays_per_s) * 1e-6);
  if (o.cache_latency) print_cache_latency(*device);
  return 0;
}

}  // namespace

std::function<int()> add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("bench", "Measure GPU time per pass and rays per second");
  add_scene_options(*cmd, o->scene);
  cmd->add_option("--warmup", o->warmup, "Frames rendered before measuring")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  cmd->add_option("--frames", o->frames, "Frames measured")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_option("--first-frame", o->first_frame, "Animation frame to start at")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  cmd->add_option("--time-step", o->time_step,
                  "Scene time per frame: below 1 the animation plays in slow motion, so that long warm-ups still "
                  "measure moving frames (light-exit moves between its frames 3 and 9)")
      ->check(CLI::Range(0.0001, 100.0))
      ->capture_default_str();
  cmd->add_option("--bandwidth-mib", o->bandwidth_mib,
                  "Size of the copy that measures the bandwidth for the floors (default: 256 on a GPU, 16 on a CPU)")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--cache-latency", o->cache_latency,
                "After the frames, time chains of dependent loads from 8 KiB to 64 MiB through a storage buffer and "
                "a sampled image: where each kind of load's cache ends (porting: hal/PORTING.md)");
  cmd->add_flag("--traffic", o->traffic,
                "After the pass table, each pass's declared images and buffers with their bytes a pixel (what its "
                "B/pixel column is made of)");
  return [o] { return run_bench(*o); };
}

}  // namespace asvgf::cli
