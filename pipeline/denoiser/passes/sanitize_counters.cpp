// asvgf::passes::SanitizeCounters (include/asvgf/sanitize_counters.hpp).
#include "asvgf/sanitize_counters.hpp"

#include <array>
#include <span>

namespace asvgf::passes {

SanitizeCounters::SanitizeCounters(hal::Device& device) : device_(device) {
  buffer_ = device_.create_buffer(
      {"sanitize_counters", kSize, hal::BufferUsage::Storage | hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst});
  const std::array<std::uint32_t, 4> zeros{};
  device_.upload_buffer(buffer_, 0, std::as_bytes(std::span(zeros)));
  state_ = hal::State::CopyDst;
}

SanitizeCounters::~SanitizeCounters() {
  device_.destroy(buffer_);
}

graph::ResourceId SanitizeCounters::import(graph::RenderGraph& graph) {
  const graph::ResourceId id = graph.import_buffer("sanitize_counters", buffer_, state_, kSize);
  // An output with a final state: the frame leaves the buffer in ShaderWrite whatever runs, so the
  // state recorded here for the next import is a guarantee, not an assumption about the passes.
  graph.output(id, hal::State::ShaderWrite);
  state_ = hal::State::ShaderWrite;
  return id;
}

SanitisedCounts SanitizeCounters::read() {
  device_.wait();
  if (state_ != hal::State::CopySrc) {
    auto cmd = device_.create_command_list("sanitize_counters readback");
    cmd->barrier({buffer_, state_, hal::State::CopySrc});
    device_.submit(*cmd);
    device_.wait();
    state_ = hal::State::CopySrc;
  }
  std::array<std::uint32_t, 4> values{};
  device_.read_buffer(buffer_, 0, std::as_writable_bytes(std::span(values)));
  return {values[0], values[1], values[2], values[3]};
}

}  // namespace asvgf::passes
