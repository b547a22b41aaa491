#include "passes/compute_pass.hpp"

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

hal::PipelineHandle PipelineCache::get(const hal::ShaderInfo& shader, std::size_t uniform_size) {
  if (auto it = pipelines_.find(&shader); it != pipelines_.end()) return it->second;
  if (uniform_size != shader.uniform_block_size)
    throw hal::Error(hal::ErrorKind::BindingMismatch, std::string(shader.name),
                     "the C++ uniform struct is " + std::to_string(uniform_size) + " bytes, the shader's block " +
                         std::to_string(shader.uniform_block_size));
  const auto pipeline = device_.create_pipeline({std::string(shader.name), &shader});
  pipelines_.emplace(&shader, pipeline);
  return pipeline;
}

graph::PassBuilder add_compute_pass(graph::RenderGraph& graph, const std::string& name, hal::PipelineHandle pipeline,
                                    std::vector<Binding> bindings, std::vector<std::byte> uniforms,
                                    std::array<std::uint32_t, 3> groups) {
  auto builder = graph.add_pass(name);
  for (const auto& b : bindings) {
    if (b.history) builder.read_history(b.resource);
    else if (graph::writes(b.use)) builder.write(b.resource, b.use);
    else builder.read(b.resource, b.use);
  }
  builder.execute([pipeline, bindings = std::move(bindings), uniforms = std::move(uniforms), groups](
                      graph::PassContext& ctx) {
    std::vector<hal::BindingSetDesc::Entry> entries;
    entries.reserve(bindings.size());
    for (const auto& b : bindings)
      entries.push_back({b.name, b.history ? ctx.history(b.resource) : ctx.resource(b.resource)});
    ctx.dispatch(pipeline, entries, uniforms, groups[0], groups[1], groups[2]);
  });
  return builder;
}

}  // namespace asvgf::passes
