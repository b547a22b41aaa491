// Internal state of the recording device: object tables, recorded commands, resource tracking.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hal/error.hpp"
#include "hal_record/record_device.hpp"

namespace hal::record {

struct BufferObject {
  BufferDesc desc;
  bool destroyed = false;
};
struct ImageObject {
  ImageDesc desc;
  bool destroyed = false;
};
struct PipelineObject {
  std::string name;
  const ShaderInfo* shader = nullptr;
  bool destroyed = false;
};
struct BindingSetObject {
  std::string name;
  PipelineHandle pipeline;
  // Parallel to the shader's bindings: the bound resource, or empty when unbound.
  std::vector<std::optional<Resource>> bound;
  bool destroyed = false;
};
struct AccelObject {
  std::string name;
  bool top_level = false;
  BlasDesc blas;  // bottom level only
  bool destroyed = false;
};
struct TimerObject {
  TimerQueriesDesc desc;
  bool destroyed = false;
};

// What a command does to one resource.
struct CommandUse {
  Resource resource;
  bool read = false;
  bool write = false;
  State needs = State::Undefined;  // the state the resource must be in
  std::string role;                // "binding 'src'", "copy source", ... for messages
};

// One recorded command; `uses` is resolved at submit time for dispatches (from the binding set).
struct Command {
  enum class Op { Barrier, Dispatch, Copy, Clear, BuildBlas, BuildTlas, Timer, Label } op = Op::Barrier;
  std::string name;  // "label/path: op object"
  std::vector<Barrier> barriers;
  DispatchDesc dispatch;  // uniforms span is not kept
  std::vector<CommandUse> uses;
  std::vector<AccelHandle> tlas_instances;
};

// Tracked state of one buffer, image or acceleration structure.
struct SimulatedState {
  State state = State::Undefined;
  bool written = false;
  std::string pending_write;               // unsynchronised writer since the last barrier
  std::vector<std::string> pending_reads;  // unsynchronised readers since the last barrier
  std::string last_change;                 // command that last set the state, for messages
};

struct RecordDevice::Impl {
  RecordOptions options;
  AdapterInfo adapter;
  std::vector<BufferObject> buffers;
  std::vector<ImageObject> images;
  std::vector<PipelineObject> pipelines;
  std::vector<BindingSetObject> binding_sets;
  std::vector<AccelObject> accels;
  std::vector<TimerObject> timers;
  std::map<std::uint64_t, SimulatedState> tracks;
  std::vector<Report> reports;
  std::vector<LogEntry> log;

  // Lookup that throws InvalidHandle for ids that were never created (destroyed ones are found).
  template <typename T>
  static T& get(std::vector<T>& table, std::uint32_t id, std::string_view what) {
    if (id == 0 || id > table.size())
      throw Error(ErrorKind::InvalidHandle, what, "handle " + std::to_string(id) + " was never created");
    return table[id - 1];
  }
  BufferObject& buffer(BufferHandle h) { return get(buffers, h.id, "buffer"); }
  ImageObject& image(ImageHandle h) { return get(images, h.id, "image"); }
  PipelineObject& pipeline(PipelineHandle h) { return get(pipelines, h.id, "pipeline"); }
  BindingSetObject& binding_set(BindingSetHandle h) { return get(binding_sets, h.id, "binding set"); }
  AccelObject& accel(AccelHandle h) { return get(accels, h.id, "acceleration structure"); }
  TimerObject& timer(TimerQueriesHandle h) { return get(timers, h.id, "timer queries"); }

  void check_exists(Resource r);  // throws InvalidHandle for never-created resources
  std::string name_of(Resource r) const;
  bool destroyed(Resource r) const;
  SimulatedState& track(Resource r) { return tracks[(std::uint64_t(r.kind) << 32) | r.id]; }

  void report(ReportKind kind, std::string resource, std::string first, std::string second, std::string message);

  // Replays one command through the tracker (tracker.cpp).
  void replay(Command& command);
  void apply_barriers(const Command& command);
  void apply_uses(const Command& command);
  std::vector<CommandUse> dispatch_uses(const Command& command);
  void append_log(const Command& command);
  // Host transfers: synchronous, so they also complete every earlier access.
  void host_access(Resource r, bool write, std::string_view what);
};

// The CommandList of the recording device (record_command_list.cpp).
std::unique_ptr<CommandList> make_record_command_list(RecordDevice::Impl& device, std::string_view name);
std::vector<Command>& recorded_commands(CommandList& list);

}  // namespace hal::record
