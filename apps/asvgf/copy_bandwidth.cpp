#include "copy_bandwidth.hpp"

#include <span>
#include <vector>

#include "report/sequence_metrics.hpp"
#include "shaders/bandwidth_copy.hpp"

namespace asvgf::cli {

std::optional<CopyBandwidth> measure_copy_bandwidth(hal::Device& device, std::uint64_t bytes, int repeats) {
  if (!device.capabilities().timestamps || repeats < 1) return std::nullopt;
  bytes -= bytes % 16;
  const auto usage = hal::BufferUsage::Storage | hal::BufferUsage::CopyDst;
  const hal::BufferHandle src = device.create_buffer({"bandwidth source", bytes, usage});
  const hal::BufferHandle dst = device.create_buffer({"bandwidth destination", bytes, usage});
  const hal::TimerQueriesHandle timers =
      device.create_timer_queries({"bandwidth copies", static_cast<std::uint32_t>(repeats)});
  const hal::PipelineHandle pipeline = device.create_pipeline({"bandwidth copy", &shaders::bandwidth_copy});
  const hal::BindingSetHandle set =
      device.create_binding_set({"bandwidth copy", pipeline, {{"src", src}, {"dst", dst}}});
  // Enough workgroups to fill any GPU, each invocation striding over the rest. A CPU device runs
  // workgroups one after another at a cost each (lavapipe's under AddressSanitizer made a 1 MiB copy
  // take 0.5 s): there a few per core.
  const bool cpu = device.adapter().type == hal::DeviceType::Cpu;
  const std::uint32_t groups = cpu ? 64 : 8192, size = shaders::bandwidth_copy.workgroup_size[0];
  shaders::bandwidth_copy_uniforms::Params params{};
  params.count = static_cast<std::uint32_t>(bytes / 16);
  params.stride = groups * size;

  auto commands = device.create_command_list("copy bandwidth");
  commands->clear_buffer(src, 0u);  // defined contents; the copy does not care which
  commands->barrier(
      {{src, hal::State::CopyDst, hal::State::ShaderRead}, {dst, hal::State::Undefined, hal::State::ShaderWrite}});
  for (int r = 0; r < repeats; ++r) {
    if (r > 0) commands->barrier({dst, hal::State::ShaderWrite, hal::State::ShaderWrite});  // one copy at a time
    commands->begin_timer(timers, static_cast<std::uint32_t>(r));
    commands->dispatch({pipeline, set, std::as_bytes(std::span(&params, 1)), groups, 1, 1});
    commands->end_timer(timers, static_cast<std::uint32_t>(r));
  }
  commands->barrier({src, hal::State::ShaderRead, hal::State::CopyDst});  // as the list starts, for the resubmissions
  // A GPU clocks up only under sustained load: resubmit until a quarter second of copies ran
  // (at most 50 times), and keep the last submission's times. A CPU has no clocks to raise.
  std::vector<double> ms;
  double total_ms = 0.0;
  const int submissions = cpu ? 1 : 50;
  for (int submission = 0; submission < submissions && (submission == 0 || total_ms < 250.0); ++submission) {
    device.submit(*commands);
    device.wait();
    ms.clear();
    for (const auto& t : device.read_timers(timers))
      if (t && *t > 0.0) ms.push_back(*t), total_ms += *t;
    if (ms.empty()) break;
  }
  commands.reset();
  device.destroy(set);
  device.destroy(pipeline);
  device.destroy(timers);
  device.destroy(dst);
  device.destroy(src);
  if (ms.empty()) return std::nullopt;
  CopyBandwidth b;
  b.bytes = bytes;
  b.median_ms = report::median(ms);
  b.bytes_per_second = 2.0 * static_cast<double>(bytes) / (b.median_ms * 1e-3);
  return b;
}

}  // namespace asvgf::cli
