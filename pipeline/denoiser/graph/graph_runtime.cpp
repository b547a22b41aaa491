// The runtime between frames: the pooled transients and both versions of each persistent resource
// (created when a compiled frame first needs them), the binding-set cache, the timers.
#include <algorithm>

#include "asvgf/graph_runtime.hpp"

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
      if (it != persistent_.end() &&
          !same_shape(Slot{d.kind, d.width, d.height, d.format, d.size, {}}, it->second.decl)) {
        // A resize: the old versions are useless (compile() already treated them as new). A frame
        // still in flight may read them.
        device_.wait();
        destroy(device_, it->second.versions[0]);
        destroy(device_, it->second.versions[1]);
        persistent_.erase(it);
        it = persistent_.end();
      }
      if (it == persistent_.end()) {
        Persistent fresh;
        fresh.decl = d;
        for (int v = 0; v < 2; ++v)
          fresh.versions[v] =
              create(device_, d.name + "[" + std::to_string(v) + "]", d.kind, d.width, d.height, d.format, d.size);
        persistent_.emplace(d.name, fresh);
      }
    }
  }
  // Each resource's HAL objects this frame, by id, so that passes need no lookups by name.
  resolved_.assign(res.size(), {});
  for (ResourceId r = 0; r < res.size(); ++r) {
    const Placement& p = frame.placement[r];
    switch (p.where) {
      case Placement::Where::Transient:
        resolved_[r][0] = slots_.at(p.slot).handle;
        break;
      case Placement::Where::Persistent: {
        const Persistent& versions = persistent_.at(res[r].name);
        resolved_[r] = {versions.versions[p.slot], versions.versions[1 - p.slot]};
        break;
      }
      case Placement::Where::Imported:
        resolved_[r][0] = res[r].imported;
        break;
      case Placement::Where::Unused:
        break;
    }
  }
}

hal::Resource GraphRuntime::physical(const CompiledFrame& frame, ResourceId id, bool history) const {
  const hal::Resource r = id < resolved_.size() ? resolved_[id][history ? 1 : 0] : hal::Resource{};
  if (!r.id)
    throw GraphError("resource '" + frame.graph->resource(id).name +
                     "' is used by a pass but was not declared in that pass");
  return r;
}

std::vector<PassTime> GraphRuntime::timings() {
  std::vector<PassTime> out;
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

}  // namespace asvgf::graph
