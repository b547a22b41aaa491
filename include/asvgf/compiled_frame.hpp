// asvgf/compiled_frame.hpp: what compiling one render graph gives: the passes in execution order
// with the barriers before each, the culled passes with reasons, where every resource lives, and
// the states the frame leaves behind. GraphRuntime::compile makes it (compile.cpp); text() and dot()
// print it (compiled_frame.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "asvgf/render_graph.hpp"

namespace asvgf::graph {

// Where a graph resource lives in this frame.
struct Placement {
  enum class Where : std::uint8_t { Unused, Transient, Persistent, Imported } where = Where::Unused;
  std::uint32_t slot = 0;  // transient pool slot, or persistent version written this frame
};

struct GraphBarrier {
  ResourceId resource = 0;
  bool history = false;  // the barrier is on last frame's version
  hal::State before = hal::State::Undefined;
  hal::State after = hal::State::Undefined;
  bool discard = false;  // a transient's slot changes hands: wait for the old owner, keep nothing
  friend bool operator==(const GraphBarrier&, const GraphBarrier&) = default;
};

struct CompiledPass {
  std::size_t pass = 0;                    // index into RenderGraph::passes()
  std::vector<ResourceId> history_clears;  // histories never written: cleared to zero first
  std::vector<GraphBarrier> barriers;      // recorded before the pass, in this order
};

struct CulledPass {
  std::string name;
  std::string reason;
};

struct MemoryReport {
  std::uint64_t transient_without_aliasing = 0;  // bytes if every transient had its own memory
  std::uint64_t transient_with_aliasing = 0;     // bytes of the pool slots actually used
  std::uint64_t persistent = 0;                  // both versions of every persistent resource
};

struct CompiledFrame {
  const RenderGraph* graph = nullptr;
  std::uint64_t frame = 0;
  std::vector<CompiledPass> passes;  // in execution order
  std::vector<CulledPass> culled;
  std::vector<GraphBarrier> final_barriers;  // after the last pass: outputs into their final states
  std::vector<Placement> placement;          // per resource
  // Per resource: last frame's version holds data this frame's passes may read (it was written
  // and not cleared here). False for resources no pass reads as a history.
  std::vector<bool> history_valid;
  // Per resource: first and last position in `passes` that touches it (transients only).
  std::vector<std::pair<int, int>> lifetime;
  MemoryReport memory;
  // States and written flags of persistent versions after this frame (applied by execute()).
  struct PersistentEnd {
    std::string name;
    std::uint32_t version = 0;
    hal::State state = hal::State::Undefined;
    bool written = false;
    bool pending_write = false, pending_read = false;  // unsynchronised accesses carried into the next frame
  };
  std::vector<PersistentEnd> persistent_end;
  std::vector<std::uint32_t> new_slots;  // pool slots this frame adds (indices into the runtime's pool)
  struct SlotEnd {
    std::uint32_t slot = 0;
    hal::State state = hal::State::Undefined;
    bool pending = false;
  };
  std::vector<SlotEnd> slot_end;  // pool slots this frame used, as it leaves them

  std::string text() const;  // readable dump: order, barriers, culled passes with reasons, memory
  std::string dot() const;   // Graphviz
};

}  // namespace asvgf::graph
