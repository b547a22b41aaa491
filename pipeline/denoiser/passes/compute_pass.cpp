#include "asvgf/compute_pass.hpp"

#include <algorithm>
#include <string>

#include "hal/error.hpp"

namespace asvgf::passes {

PipelineCache::~PipelineCache() {
  try {
    device_.wait();
    for (auto& [shader, pipeline] : pipelines_) device_.destroy(pipeline);
  } catch (...) {
    // A lost device has nothing left to release.
  }
}

hal::PipelineHandle PipelineCache::get(const hal::ShaderInfo& shader, std::size_t size,
                                       const hal::ShaderInfo& layout_of) {
  if (auto it = pipelines_.find(&shader); it != pipelines_.end()) return it->second;
  const std::string object(shader.name);
  const std::string cpp = "the C++ struct generated from '" + std::string(layout_of.name) + "'";
  if (shader.uniform_block_size != size)
    throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                     "uniform block is " + std::to_string(shader.uniform_block_size) + " bytes in the shader, " +
                         std::to_string(size) + " in " + cpp);
  const auto& ours = shader.uniform_members;
  const auto& theirs = layout_of.uniform_members;
  for (std::size_t i = 0; i < std::max(ours.size(), theirs.size()); ++i) {
    if (i >= ours.size() || i >= theirs.size() || ours[i].name != theirs[i].name)
      throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                       "uniform member " + std::to_string(i) + " is '" +
                           (i < ours.size() ? std::string(ours[i].name) : "none") + "' in the shader, '" +
                           (i < theirs.size() ? std::string(theirs[i].name) : "none") + "' in " + cpp);
    if (ours[i].offset != theirs[i].offset || ours[i].size != theirs[i].size)
      throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                       "uniform member '" + std::string(ours[i].name) + "' is at offset " +
                           std::to_string(ours[i].offset) + " in the shader, " + std::to_string(theirs[i].offset) +
                           " in " + cpp);
  }
  const auto pipeline = device_.create_pipeline({object, &shader});
  pipelines_.emplace(&shader, pipeline);
  return pipeline;
}

namespace {

graph::Use use_of(const hal::ShaderBinding& b) {
  if (b.kind == hal::BindingKind::AccelerationStructure) return graph::Use::AccelRead;
  switch (b.access) {
    case hal::Access::Read:
      return graph::Use::ShaderRead;
    case hal::Access::Write:
      return graph::Use::ShaderWrite;
    case hal::Access::ReadWrite:
      return graph::Use::ShaderReadWrite;
  }
  return graph::Use::ShaderReadWrite;
}

[[noreturn]] void mismatch(const std::string& pass, const hal::ShaderInfo& shader, const std::string& problem) {
  throw hal::Error(hal::ErrorKind::BindingMismatch, std::string(shader.name), "pass '" + pass + "': " + problem);
}

}  // namespace

graph::PassBuilder add_compute_pass(graph::RenderGraph& graph, const std::string& name, const hal::ShaderInfo& shader,
                                    hal::PipelineHandle pipeline, std::vector<Binding> bindings,
                                    std::vector<std::byte> uniforms, std::array<std::uint32_t, 3> invocations,
                                    UniformsAtExecution at_execution) {
  if (uniforms.size() != shader.uniform_block_size)
    mismatch(name, shader,
             std::to_string(uniforms.size()) + " bytes of uniforms for the shader's block of " +
                 std::to_string(shader.uniform_block_size));
  for (std::size_t i = 0; i < bindings.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (bindings[i].name == bindings[j].name)
        mismatch(name, shader, "binding '" + bindings[i].name + "' is given twice");
  for (const auto& sb : shader.bindings) {
    if (sb.kind == hal::BindingKind::UniformBuffer) continue;  // filled from `uniforms`
    bool bound = false;
    for (const auto& b : bindings) bound = bound || b.name == sb.name;
    if (!bound) mismatch(name, shader, "shader binding '" + std::string(sb.name) + "' is left unbound");
  }
  auto builder = graph.add_pass(name);
  for (const auto& b : bindings) {
    const hal::ShaderBinding* sb = shader.find(b.name);
    if (!sb || sb->kind == hal::BindingKind::UniformBuffer)
      mismatch(name, shader, "the shader has no binding '" + b.name + "'");
    const graph::Use use = use_of(*sb);
    if (b.history) {
      if (graph::writes(use)) mismatch(name, shader, "history binding '" + b.name + "' is written by the shader");
      builder.read_history(b.resource);
    } else if (graph::writes(use)) {
      builder.write(b.resource, use);
    } else {
      builder.read(b.resource, use);
    }
  }
  std::array<std::uint32_t, 3> groups{};
  for (int axis = 0; axis < 3; ++axis)
    groups[static_cast<std::size_t>(axis)] =
        groups_for(invocations[static_cast<std::size_t>(axis)], shader.workgroup_size[static_cast<std::size_t>(axis)]);
  builder.execute([pipeline, bindings = std::move(bindings), uniforms = std::move(uniforms), groups,
                   at_execution = std::move(at_execution)](graph::PassContext& ctx) {
    std::vector<hal::BindingSetDesc::Entry> entries;
    entries.reserve(bindings.size());
    for (const auto& b : bindings)
      entries.push_back({b.name, b.history ? ctx.history(b.resource) : ctx.resource(b.resource)});
    if (!at_execution) {
      ctx.dispatch(pipeline, entries, uniforms, groups[0], groups[1], groups[2]);
      return;
    }
    std::vector<std::byte> values = uniforms;
    at_execution(ctx, values);
    ctx.dispatch(pipeline, entries, values, groups[0], groups[1], groups[2]);
  });
  return builder;
}

}  // namespace asvgf::passes
