#include "passes/compute_pass.hpp"

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

void check_uniform_layout(const hal::ShaderInfo& shader, std::size_t size, std::initializer_list<UniformField> fields) {
  const std::string object(shader.name);
  if (shader.uniform_block_size != size)
    throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                     "uniform block is " + std::to_string(shader.uniform_block_size) + " bytes in the shader, " +
                         std::to_string(size) + " in C++");
  for (const UniformField& f : fields) {
    const hal::UniformMember* found = nullptr;
    for (const auto& m : shader.uniform_members)
      if (m.name == f.name) found = &m;
    if (!found)
      throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                       "uniform member '" + std::string(f.name) + "' of the C++ struct is not in the shader");
    if (found->offset != f.offset)
      throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                       "uniform member '" + std::string(f.name) + "' is at offset " + std::to_string(found->offset) +
                           " in the shader, " + std::to_string(f.offset) + " in C++");
  }
  if (shader.uniform_members.size() != fields.size())
    throw hal::Error(hal::ErrorKind::BindingMismatch, object,
                     "the shader's uniform block has " + std::to_string(shader.uniform_members.size()) +
                         " members, the C++ struct " + std::to_string(fields.size()));
}

hal::PipelineHandle PipelineCache::get(const hal::ShaderInfo& shader, std::size_t uniform_size,
                                       std::initializer_list<UniformField> fields) {
  if (auto it = pipelines_.find(&shader); it != pipelines_.end()) return it->second;
  if (fields.size() > 0) check_uniform_layout(shader, uniform_size, fields);
  if (uniform_size != shader.uniform_block_size)
    throw hal::Error(hal::ErrorKind::BindingMismatch, std::string(shader.name),
                     "the C++ uniform struct is " + std::to_string(uniform_size) + " bytes, the shader's block " +
                         std::to_string(shader.uniform_block_size));
  const auto pipeline = device_.create_pipeline({std::string(shader.name), &shader});
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
