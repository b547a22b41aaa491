// Executing a compiled frame: creating pooled and persistent resources, recording passes with
// labels, barriers and timer regions, and advancing the ping-pong.
#include <algorithm>

#include "graph/graph_runtime.hpp"

namespace asvgf::graph {
namespace {

constexpr auto kImageUsage =
    hal::ImageUsage::Sampled | hal::ImageUsage::Storage | hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst;
constexpr auto kBufferUsage = hal::BufferUsage::Storage | hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst;

hal::Resource create(hal::Device& device, const std::string& name, hal::ResourceKind kind, std::uint32_t width,
                     std::uint32_t height, hal::Format format, std::uint64_t size) {
  if (kind == hal::ResourceKind::Buffer) return device.create_buffer({name, size, kBufferUsage});
  return device.create_image({name, width, height, format, kImageUsage});
}

void destroy(hal::Device& device, hal::Resource r) {
  if (!r.id) return;
  if (r.kind == hal::ResourceKind::Buffer) device.destroy(hal::BufferHandle{r.id});
  if (r.kind == hal::ResourceKind::Image) device.destroy(hal::ImageHandle{r.id});
}

}  // namespace

GraphRuntime::GraphRuntime(hal::Device& device) : device_(device) {}

GraphRuntime::~GraphRuntime() {
  try {
    device_.wait();
    for (auto& [key, set] : binding_sets_) device_.destroy(set);
    for (auto& s : slots_) destroy(device_, s.handle);
    for (auto& [name, p] : persistent_) destroy(device_, p.versions[0]), destroy(device_, p.versions[1]);
    if (timers_) device_.destroy(timers_);
  } catch (...) {
    // Destruction must not throw; a lost device has nothing left to release.
  }
}

void GraphRuntime::ensure_resources(const CompiledFrame& frame) {
  const auto& res = frame.graph->resources();
  for (std::uint32_t s : frame.new_slots) {
    if (s < slots_.size()) continue;
    slots_.resize(s + 1);
  }
  for (ResourceId r = 0; r < res.size(); ++r) {
    const Placement& p = frame.placement[r];
    const ResourceDecl& d = res[r];
    if (p.where == Placement::Where::Transient) {
      Slot& slot = slots_[p.slot];
      if (!slot.handle.id) {
        slot = {d.kind, d.width, d.height, d.format, d.size, {}, hal::State::Undefined, false};
        slot.handle = create(device_, "transient." + std::to_string(p.slot) + " (" + d.name + ")", d.kind, d.width,
                             d.height, d.format, d.size);
      }
    } else if (p.where == Placement::Where::Persistent) {
      auto it = persistent_.find(d.name);
      if (it != persistent_.end() && !same_shape(Slot{d.kind, d.width, d.height, d.format, d.size, {}}, it->second.decl)) {
        // A resize: the old versions are useless (compile() already treated them as new).
        destroy(device_, it->second.versions[0]);
        destroy(device_, it->second.versions[1]);
        persistent_.erase(it);
        it = persistent_.end();
      }
      if (it == persistent_.end()) {
        Persistent fresh;
        fresh.decl = d;
        for (int v = 0; v < 2; ++v)
          fresh.versions[v] = create(device_, d.name + "[" + std::to_string(v) + "]", d.kind, d.width, d.height,
                                     d.format, d.size);
        persistent_.emplace(d.name, fresh);
      }
    }
  }
}

hal::Resource GraphRuntime::physical(const CompiledFrame& frame, ResourceId id, bool history) {
  const ResourceDecl& d = frame.graph->resource(id);
  const Placement& p = frame.placement.at(id);
  switch (p.where) {
    case Placement::Where::Transient: return slots_.at(p.slot).handle;
    case Placement::Where::Persistent: return persistent_.at(d.name).versions[history ? 1 - p.slot : p.slot];
    case Placement::Where::Imported: return d.imported;
    case Placement::Where::Unused: break;
  }
  throw GraphError("resource '" + d.name + "' is used by a pass but was not declared in that pass");
}

void GraphRuntime::execute(const CompiledFrame& frame, hal::CommandList& commands) {
  if (frame.frame != frame_)
    throw GraphError("compiled frame " + std::to_string(frame.frame) + " executed at frame " + std::to_string(frame_));
  ensure_resources(frame);
  const auto regions = static_cast<std::uint32_t>(std::max<std::size_t>(1, frame.passes.size()));
  if (regions > timer_regions_) {
    if (timers_) device_.destroy(timers_);
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
      if (h.kind == hal::ResourceKind::Image) commands.clear_image(hal::ImageHandle{h.id}, {0, 0, 0, 0});
      else commands.clear_buffer(hal::BufferHandle{h.id}, 0);
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

std::vector<PassTiming> GraphRuntime::timings() {
  std::vector<PassTiming> out;
  if (!timers_) return out;
  const auto ms = device_.read_timers(timers_);
  for (std::size_t i = 0; i < timed_passes_.size(); ++i)
    out.push_back({timed_passes_[i], i < ms.size() ? ms[i] : std::nullopt});
  return out;
}

void GraphRuntime::reset_histories() {
  for (auto& [name, p] : persistent_) p.written[0] = p.written[1] = false;
}

hal::BindingSetHandle GraphRuntime::binding_set(hal::PipelineHandle pipeline,
                                                const std::vector<hal::BindingSetDesc::Entry>& entries) {
  std::string key = std::to_string(pipeline.id);
  for (const auto& e : entries)
    key += "|" + e.name + "=" + std::to_string(int(e.resource.kind)) + ":" + std::to_string(e.resource.id);
  auto it = binding_sets_.find(key);
  if (it != binding_sets_.end()) return it->second;
  const auto set = device_.create_binding_set({"bindings " + key, pipeline, entries});
  binding_sets_.emplace(key, set);
  return set;
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
  const auto& d = compiled_.graph->resource(id);
  auto it = runtime_.persistent_.find(d.name);
  if (it == runtime_.persistent_.end()) return false;
  for (const auto& cp : compiled_.passes)
    for (ResourceId r : cp.history_clears)
      if (r == id) return false;
  return it->second.written[1 - compiled_.placement.at(id).slot];
}

void PassContext::dispatch(hal::PipelineHandle pipeline, const std::vector<hal::BindingSetDesc::Entry>& entries,
                           std::span<const std::byte> uniforms, std::uint32_t gx, std::uint32_t gy, std::uint32_t gz) {
  commands_.dispatch({pipeline, runtime_.binding_set(pipeline, entries), uniforms, gx, gy, gz});
}

}  // namespace asvgf::graph
