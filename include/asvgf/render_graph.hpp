// asvgf/render_graph.hpp: a frame as passes with declared reads and writes.
//
// A RenderGraph is rebuilt every frame (cheap: names, ids, callbacks). It is compiled by a
// GraphRuntime (graph_runtime.hpp), which owns the GPU resources across frames: it culls passes
// that contribute nothing, orders the rest, derives barriers from the declarations and the
// resources' current states, aliases transient resources whose lifetimes do not overlap, and
// ping-pongs persistent resources so that a pass can read last frame's version (a history).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hal/device.hpp"

namespace asvgf::graph {

using ResourceId = std::uint32_t;

// What a pass does to a resource; decides the HAL state it needs.
enum class Use : std::uint8_t { ShaderRead, ShaderWrite, ShaderReadWrite, CopySrc, CopyDst, AccelRead };
hal::State required_state(Use use);
bool reads(Use use);
bool writes(Use use);

enum class Lifetime : std::uint8_t {
  Transient,   // lives within one frame; memory may be shared with other transients
  Persistent,  // kept across frames in two versions; last frame's is readable as a history
  Imported,    // owned outside the graph (scene buffers, acceleration structures), already written
};

struct ResourceDecl {
  std::string name;
  hal::ResourceKind kind = hal::ResourceKind::Image;
  Lifetime lifetime = Lifetime::Transient;
  std::uint32_t width = 0, height = 0;
  hal::Format format = hal::Format::Undefined;
  std::uint64_t size = 0;  // buffers
  hal::Resource imported;  // imported only
  hal::State imported_state = hal::State::Undefined;
};

struct PassAccess {
  ResourceId resource = 0;
  Use use = Use::ShaderRead;
  bool history = false;  // reads last frame's version of a persistent resource
};

class PassContext;
using ExecuteFn = std::function<void(PassContext&)>;

struct PassDecl {
  std::string name;
  std::vector<PassAccess> accesses;
  ExecuteFn execute;
  std::string skip_reason;  // not empty: the pass is left out of this frame, for this reason
};

// A compile error: names the pass and the resource.
class GraphError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class RenderGraph;

// Chained declaration of one pass: graph.add_pass("x").read(a).write(b).execute(fn).
class PassBuilder {
 public:
  PassBuilder(RenderGraph& graph, std::size_t index) : graph_(graph), index_(index) {}
  PassBuilder& read(ResourceId r, Use use = Use::ShaderRead);
  PassBuilder& read_history(ResourceId r);
  PassBuilder& write(ResourceId r, Use use = Use::ShaderWrite);
  PassBuilder& read_write(ResourceId r);
  PassBuilder& skip_if(bool condition, std::string reason);
  PassBuilder& execute(ExecuteFn fn);

 private:
  PassDecl& pass();
  RenderGraph& graph_;
  std::size_t index_;
};

class RenderGraph {
 public:
  ResourceId add_image(std::string name, std::uint32_t width, std::uint32_t height, hal::Format format,
                       Lifetime lifetime = Lifetime::Transient);
  ResourceId add_buffer(std::string name, std::uint64_t size, Lifetime lifetime = Lifetime::Transient);
  // An object owned outside the graph, in `state` now. Images give their size so that passes can
  // size their dispatches from the declaration, and their format so that the bytes passes move
  // through them can be counted (pass_traffic.hpp); Undefined leaves them uncounted.
  ResourceId import(std::string name, hal::Resource resource, hal::State state, std::uint32_t width = 0,
                    std::uint32_t height = 0, hal::Format format = hal::Format::Undefined);
  // An imported buffer of known size (counted by pass_traffic; import() leaves buffers uncounted).
  ResourceId import_buffer(std::string name, hal::BufferHandle buffer, hal::State state, std::uint64_t size);
  PassBuilder add_pass(std::string name);
  // Resources the frame exists to produce; passes that contribute to none of them are culled.
  // With `final_state`, the frame ends with a barrier moving the resource there (e.g. CopySrc for
  // a host readback after the frame).
  void output(ResourceId resource, std::optional<hal::State> final_state = std::nullopt);
  const std::vector<std::optional<hal::State>>& output_states() const { return output_states_; }

  const std::vector<ResourceDecl>& resources() const { return resources_; }
  const std::vector<PassDecl>& passes() const { return passes_; }
  std::vector<PassDecl>& passes() { return passes_; }
  const std::vector<ResourceId>& outputs() const { return outputs_; }
  const ResourceDecl& resource(ResourceId id) const { return resources_.at(id); }
  // The resource with this name; throws GraphError when there is none.
  ResourceId find(const std::string& name) const;

 private:
  std::vector<ResourceDecl> resources_;
  std::vector<PassDecl> passes_;
  std::vector<ResourceId> outputs_;
  std::vector<std::optional<hal::State>> output_states_;
};

}  // namespace asvgf::graph
