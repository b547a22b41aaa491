// asvgf/compute_pass.hpp: what every compute pass shares: pipelines made from the generated shader
// headers (their uniform block checked against the generated C++ struct), and declaring a dispatch in the render graph
// from one binding list, so that what the graph knows and what the shader binds cannot drift:
// whether a binding is read or written comes from the shader's reflection, every name must be one
// of the shader's bindings and every shader binding must be bound, and the workgroup counts come
// from the shader's workgroup size.
#pragma once

#include <array>
#include <cstddef>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "asvgf/graph_runtime.hpp"
#include "hal/device.hpp"

namespace asvgf::passes {

// Creates pipelines on first use and destroys them with itself.
class PipelineCache {
 public:
  explicit PipelineCache(hal::Device& device) : device_(device) {}
  ~PipelineCache();
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;

  // The pipeline of `shader`, filled with `Uniforms`: the struct the shader tool generated for this
  // shader or another variant of it (shaders::<name>_uniforms::Params). Throws
  // hal::Error(BindingMismatch) naming the shader and member when the variant's block differs.
  template <typename Uniforms>
  hal::PipelineHandle get(const hal::ShaderInfo& shader) {
    return get(shader, sizeof(Uniforms), Uniforms::shader);
  }
  // The same for a struct of `size` bytes reflected from `layout_of`.
  hal::PipelineHandle get(const hal::ShaderInfo& shader, std::size_t size, const hal::ShaderInfo& layout_of);
  hal::Device& device() { return device_; }

 private:
  hal::Device& device_;
  std::map<const hal::ShaderInfo*, hal::PipelineHandle> pipelines_;
};

struct Binding {
  std::string name;  // the shader's binding name
  graph::ResourceId resource = 0;
  bool history = false;  // bind last frame's version (the shader must only read it)
};

template <typename T>
std::vector<std::byte> to_bytes(const T& value) {
  std::vector<std::byte> bytes(sizeof(T));
  std::memcpy(bytes.data(), &value, sizeof(T));
  return bytes;
}

inline std::uint32_t groups_for(std::uint32_t size, std::uint32_t group) {
  return (size + group - 1) / group;
}

// Uniform values known only when the pass executes (e.g. whether its histories hold anything):
// called with the declared bytes just before the dispatch, it may change them.
using UniformsAtExecution = std::function<void(graph::PassContext& context, std::vector<std::byte>& uniforms)>;

// Declares every binding in the graph, with the use its reflection gives (read, write, read-write,
// acceleration-structure read), and dispatches `pipeline` (made from `shader`) with them and
// `uniforms` over `invocations` threads per axis (the groups cover them). Throws
// hal::Error(BindingMismatch) naming the pass, the shader and the binding when a name is not one of
// the shader's bindings, a shader binding is left unbound, a binding is given twice, a history
// binding is written, or `uniforms` is not the size of the shader's block.
graph::PassBuilder add_compute_pass(graph::RenderGraph& graph, const std::string& name, const hal::ShaderInfo& shader,
                                    hal::PipelineHandle pipeline, std::vector<Binding> bindings,
                                    std::vector<std::byte> uniforms, std::array<std::uint32_t, 3> invocations,
                                    UniformsAtExecution at_execution = {});

}  // namespace asvgf::passes
