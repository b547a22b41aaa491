// Long runs: 10,000 frames of every method at 16x16 with the scene moving every frame (the orbit
// played in slow motion, so the gradient passes run throughout). After a warm-up of 200 frames the
// process's resident memory and the device memory the HAL holds must stay flat, every frame must be
// finite, and every pass's GPU time non-negative (timestamps in order).
#include <doctest/doctest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "hal/validate.hpp"
#include "hal_vulkan/vulkan.hpp"
#include "renderer/renderer.hpp"
#include "renderer/scene/builtin.hpp"

using namespace asvgf;

namespace {

constexpr int kFrames = 10000, kWarmup = 200;

// Resident set size of this process in bytes (/proc/self/statm, second field, in pages).
std::uint64_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

}  // namespace

TEST_CASE("soak: 10,000 frames of every method keep host and device memory flat, frames finite, timers in order") {
  // The validation layers would dominate the run time; the HAL's own validation layer stays on.
  const auto device = hal::validate::wrap(hal::vulkan::create_device({}));
  const scene::Scene scene = scene::builtin_scene("cornell", "orbit");
  for (const frame::Method method : frame::kAllMethods) {
    const std::string name(frame::to_string(method));
    CAPTURE(name);
    render::RenderSettings s;
    s.method = method;
    s.width = 16;
    s.height = 16;
    s.time_per_frame = static_cast<float>(scene.frame_count) / kFrames;  // one orbit over the run
    render::Renderer renderer(*device, scene, s);
    std::uint64_t rss_after_warmup = 0, device_after_warmup = 0, rss_peak = 0, device_peak = 0;
    int non_finite = 0, negative_times = 0, still = 0;
    for (int f = 0; f < kFrames; ++f) {
      const render::FrameImages images = renderer.render(f);
      for (const float v : images.hdr) non_finite += !std::isfinite(v);
      for (const auto& t : renderer.timings()) negative_times += t.gpu_ms && *t.gpu_ms < 0.0;
      still += f > 0 && !renderer.moved_last_frame();
      const std::uint64_t rss = resident_bytes(), dev = device->device_memory_bytes().value_or(0);
      if (f == kWarmup) rss_after_warmup = rss, device_after_warmup = dev;
      if (f >= kWarmup) rss_peak = std::max(rss_peak, rss), device_peak = std::max(device_peak, dev);
    }
    MESSAGE(name << ": " << kFrames << " frames (" << still << " still); resident memory " << rss_after_warmup / 1024
                 << " KiB after warm-up, peak " << rss_peak / 1024 << " KiB; device memory "
                 << device_after_warmup / 1024 << " KiB, peak " << device_peak / 1024 << " KiB");
    CHECK(non_finite == 0);
    CHECK(negative_times == 0);
    CHECK(still == 0);
    CHECK(device_after_warmup > 0);
    CHECK(device_peak == device_after_warmup);
    // Flat: allocator and driver noise stays within 2 MiB, while a leak of one 16x16 RGBA32F image
    // (4 KiB) a frame would grow by 39 MiB.
    CHECK(rss_peak <= rss_after_warmup + (2u << 20));
  }
}
