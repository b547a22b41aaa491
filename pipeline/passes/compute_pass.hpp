// passes/compute_pass.hpp: what every compute pass shares: pipelines made from the generated shader
// headers (checked against the C++ uniform struct), and declaring a dispatch in the render graph
// from one binding list, so that what the graph knows and what the shader binds cannot drift.
#pragma once

#include <array>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "graph/graph_runtime.hpp"
#include "hal/device.hpp"

namespace asvgf::passes {

// Creates pipelines on first use and destroys them with itself.
class PipelineCache {
 public:
  explicit PipelineCache(hal::Device& device) : device_(device) {}
  ~PipelineCache();
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;

  // Throws hal::Error(BindingMismatch) when `uniform_size` is not the shader's uniform block size.
  hal::PipelineHandle get(const hal::ShaderInfo& shader, std::size_t uniform_size);
  hal::Device& device() { return device_; }

 private:
  hal::Device& device_;
  std::map<const hal::ShaderInfo*, hal::PipelineHandle> pipelines_;
};

struct Binding {
  std::string name;  // the shader's binding name
  graph::ResourceId resource = 0;
  graph::Use use = graph::Use::ShaderRead;
  bool history = false;  // bind last frame's version
};

template <typename T>
std::vector<std::byte> to_bytes(const T& value) {
  std::vector<std::byte> bytes(sizeof(T));
  std::memcpy(bytes.data(), &value, sizeof(T));
  return bytes;
}

inline std::uint32_t groups_for(std::uint32_t size, std::uint32_t group) { return (size + group - 1) / group; }

// Declares every binding in the graph and dispatches `pipeline` with them and `uniforms`.
graph::PassBuilder add_compute_pass(graph::RenderGraph& graph, const std::string& name, hal::PipelineHandle pipeline,
                                    std::vector<Binding> bindings, std::vector<std::byte> uniforms,
                                    std::array<std::uint32_t, 3> groups);

}  // namespace asvgf::passes
