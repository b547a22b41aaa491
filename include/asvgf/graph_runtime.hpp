// asvgf/graph_runtime.hpp: compiling and executing render graphs frame after frame.
//
// The runtime owns the HAL resources behind graph resources: a pool of transient images and
// buffers (shared by transients whose lifetimes do not overlap), two versions of every persistent
// resource (ping-ponged: frame f writes version f%2 and reads last frame's as its history), and the
// timer queries. compile() needs the runtime because barriers depend on the states resources were
// left in by the previous frame. compile.cpp compiles, execute.cpp records a frame, and
// graph_runtime.cpp keeps the resources, binding sets and timers between frames.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "asvgf/compiled_frame.hpp"
#include "asvgf/denoiser_stats.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::graph {

class PassContext {
 public:
  hal::CommandList& commands() { return commands_; }
  // The HAL object behind a resource this frame, and behind last frame's version.
  hal::Resource resource(ResourceId id) const;
  hal::Resource history(ResourceId id) const;
  hal::ImageHandle image(ResourceId id) const { return hal::ImageHandle{resource(id).id}; }
  // False when last frame's version holds nothing yet (first frame, after reset): it reads zeros.
  bool history_valid(ResourceId id) const;
  // Dispatch with bindings by shader name; binding sets are cached by the runtime.
  void dispatch(hal::PipelineHandle pipeline, const std::vector<hal::BindingSetDesc::Entry>& entries,
                std::span<const std::byte> uniforms, std::uint32_t groups_x, std::uint32_t groups_y = 1,
                std::uint32_t groups_z = 1);

 private:
  friend class GraphRuntime;
  PassContext(class GraphRuntime& runtime, hal::CommandList& commands, const CompiledFrame& frame, const PassDecl& pass)
      : runtime_(runtime), commands_(commands), compiled_(frame), pass_(pass) {}
  void check_declared(ResourceId id, bool history) const;
  GraphRuntime& runtime_;
  hal::CommandList& commands_;
  const CompiledFrame& compiled_;
  const PassDecl& pass_;
};

class GraphRuntime {
 public:
  explicit GraphRuntime(hal::Device& device);
  ~GraphRuntime();
  GraphRuntime(const GraphRuntime&) = delete;
  GraphRuntime& operator=(const GraphRuntime&) = delete;

  // Culls, orders, places resources and derives barriers; throws GraphError naming the pass and
  // the resource on a read of something nothing writes, a cycle, or unordered writers.
  CompiledFrame compile(const RenderGraph& graph);
  // Records the frame (labels, barriers, history clears, a timer region per pass) and advances
  // the runtime to the next frame. The caller submits `commands`.
  void execute(const CompiledFrame& frame, hal::CommandList& commands);
  // GPU time per pass of the last executed frame; call after the device finished it.
  std::vector<PassTime> timings();
  // Forgets every history (camera cut, resize): the next frame sees none as valid.
  void reset_histories();
  // On (the default): a pass may only bind resources it declared, else execute() throws
  // GraphError. Off: what it binds is not checked (tests use this to show that the recording HAL
  // catches the missing barriers an undeclared access causes).
  void set_binding_checks(bool on) { binding_checks_ = on; }
  std::uint64_t frame() const { return frame_; }

 private:
  friend class PassContext;
  // A pooled transient: reused by any transient of the same kind, size and format.
  struct Slot {
    hal::ResourceKind kind = hal::ResourceKind::Image;
    std::uint32_t width = 0, height = 0;
    hal::Format format = hal::Format::Undefined;
    std::uint64_t size = 0;
    hal::Resource handle;                      // created on first execute
    hal::State state = hal::State::Undefined;  // at the end of the last executed frame
    bool pending = false;                      // accessed since its last barrier
  };
  struct Persistent {
    ResourceDecl decl;
    hal::Resource versions[2];
    hal::State state[2] = {hal::State::Undefined, hal::State::Undefined};
    bool written[2] = {false, false};
    bool pending_write[2] = {false, false};
    bool pending_read[2] = {false, false};
  };
  bool same_shape(const Slot& slot, const ResourceDecl& decl) const;
  // The last two phases of compile() (compile.cpp): placement of every used resource, then barriers.
  void place(CompiledFrame& out, const std::vector<std::size_t>& order,
             const std::vector<std::vector<PassAccess>>& accesses);
  void derive_barriers(CompiledFrame& out, const std::vector<std::size_t>& order,
                       const std::vector<std::vector<PassAccess>>& accesses);
  hal::Resource physical(const CompiledFrame& frame, ResourceId id, bool history) const;
  // Creates what `frame` needs that does not exist yet, then resolves every resource's HAL objects.
  void ensure_resources(const CompiledFrame& frame);
  hal::BindingSetHandle binding_set(hal::PipelineHandle pipeline, const std::vector<hal::BindingSetDesc::Entry>& e);

  hal::Device& device_;
  bool binding_checks_ = true;
  std::uint64_t frame_ = 0;
  std::vector<Slot> slots_;
  std::map<std::string, Persistent> persistent_;        // by name: graphs are rebuilt every frame
  std::vector<std::array<hal::Resource, 2>> resolved_;  // per resource of the frame executing: now, history
  std::map<std::string, hal::BindingSetHandle> binding_sets_;
  hal::TimerQueriesHandle timers_;
  std::uint32_t timer_regions_ = 0;
  std::vector<std::string> timed_passes_;
};

}  // namespace asvgf::graph
