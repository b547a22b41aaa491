// Executing a compiled frame: recording passes with labels, barriers and timer regions, advancing
// the ping-pong, and what a pass sees of it (PassContext).
#include <algorithm>

#include "asvgf/graph_runtime.hpp"

namespace asvgf::graph {

void GraphRuntime::execute(const CompiledFrame& frame, hal::CommandList& commands) {
  if (frame.frame != frame_)
    throw GraphError("compiled frame " + std::to_string(frame.frame) + " executed at frame " + std::to_string(frame_));
  ensure_resources(frame);
  const auto regions = static_cast<std::uint32_t>(std::max<std::size_t>(1, frame.passes.size()));
  if (regions > timer_regions_) {
    // A frame still in flight may use the old pool (record-and-submit callers need not wait).
    if (timers_) {
      device_.wait();
      device_.destroy(timers_);
    }
    timers_ = device_.create_timer_queries({"graph.timers", regions});
    timer_regions_ = regions;
  }
  timed_passes_.clear();
  const auto& passes = frame.graph->passes();
  for (std::uint32_t k = 0; k < frame.passes.size(); ++k) {
    const CompiledPass& cp = frame.passes[k];
    const PassDecl& pass = passes[cp.pass];
    commands.begin_label(pass.name);
    for (ResourceId r : cp.history_clears) {
      const hal::Resource h = physical(frame, r, true);
      commands.barrier({h, hal::State::Undefined, hal::State::CopyDst});
      if (h.kind == hal::ResourceKind::Image)
        commands.clear_image(hal::ImageHandle{h.id}, {0, 0, 0, 0});
      else
        commands.clear_buffer(hal::BufferHandle{h.id}, 0);
    }
    std::vector<hal::Barrier> barriers;
    for (const GraphBarrier& b : cp.barriers)
      barriers.push_back({physical(frame, b.resource, b.history), b.before, b.after, b.discard});
    if (!barriers.empty()) commands.barrier(barriers);
    commands.begin_timer(timers_, k);
    if (pass.execute) {
      PassContext context(*this, commands, frame, pass);
      pass.execute(context);
    }
    commands.end_timer(timers_, k);
    commands.end_label();
    timed_passes_.push_back(pass.name);
  }
  if (!frame.final_barriers.empty()) {
    std::vector<hal::Barrier> barriers;
    for (const GraphBarrier& b : frame.final_barriers)
      barriers.push_back({physical(frame, b.resource, false), b.before, b.after});
    commands.barrier(barriers);
  }
  for (const auto& end : frame.slot_end) {
    slots_.at(end.slot).state = end.state;
    slots_.at(end.slot).pending = end.pending;
  }
  for (const auto& end : frame.persistent_end) {
    auto& p = persistent_.at(end.name);
    p.state[end.version] = end.state;
    p.written[end.version] = end.written;
    p.pending_write[end.version] = end.pending_write;
    p.pending_read[end.version] = end.pending_read;
  }
  ++frame_;
}

void PassContext::check_declared(ResourceId id, bool history) const {
  if (!runtime_.binding_checks_) return;
  for (const PassAccess& a : pass_.accesses)
    if (a.resource == id && a.history == history) return;
  throw GraphError("pass '" + pass_.name + "' binds " + (history ? "the history of '" : "'") +
                   compiled_.graph->resource(id).name + "' but does not declare it");
}

hal::Resource PassContext::resource(ResourceId id) const {
  check_declared(id, false);
  return runtime_.physical(compiled_, id, false);
}
hal::Resource PassContext::history(ResourceId id) const {
  check_declared(id, true);
  return runtime_.physical(compiled_, id, true);
}
bool PassContext::history_valid(ResourceId id) const {
  return compiled_.history_valid.at(id);
}

void PassContext::dispatch(hal::PipelineHandle pipeline, const std::vector<hal::BindingSetDesc::Entry>& entries,
                           std::span<const std::byte> uniforms, std::uint32_t gx, std::uint32_t gy, std::uint32_t gz) {
  commands_.dispatch({pipeline, runtime_.binding_set(pipeline, entries), uniforms, gx, gy, gz});
}

}  // namespace asvgf::graph
