// What the validation layer remembers of every object it saw created, keyed by the inner device's
// handle ids, so that later calls can be checked against descriptors and reflection.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "hal/device.hpp"
#include "hal/error.hpp"

namespace hal::validate {

struct BufferInfo {
  BufferDesc desc;
  const std::string& name() const { return desc.name; }
};
struct ImageInfo {
  ImageDesc desc;
  const std::string& name() const { return desc.name; }
  std::uint64_t bytes() const { return std::uint64_t{desc.width} * desc.height * format_size(desc.format); }
};
struct PipelineInfo {
  std::string label;
  const ShaderInfo* shader = nullptr;
  const std::string& name() const { return label; }
};
struct BindingSetInfo {
  std::string label;
  const ShaderInfo* shader = nullptr;
  std::vector<Resource> bound;  // parallel to shader->bindings; id 0: unbound (or the uniform block)
  const std::string& name() const { return label; }
};
struct AccelInfo {
  std::string label;
  bool top = false;
  BlasDesc blas;       // bottom level
  TlasDesc tlas;       // top level
  bool built = false;  // a build was recorded (an update needs one)
  std::uint32_t built_instances = 0;
  const std::string& name() const { return label; }
};
struct TimerInfo {
  TimerQueriesDesc desc;
  const std::string& name() const { return desc.name; }
};

// Objects of one kind. Destroyed entries stay, so that a later use says "destroyed" rather than
// "never created"; an id the inner device hands out again replaces its entry.
template <typename T>
class Table {
 public:
  explicit Table(std::string_view kind) : kind_(kind) {}
  void add(std::uint32_t id, T info) { entries_[id] = Entry{std::move(info), false}; }
  // The live object, else InvalidHandle naming it (or the kind and id when it never existed).
  T& get(std::uint32_t id) {
    Entry& e = find(id);
    if (e.destroyed) throw Error(ErrorKind::InvalidHandle, e.info.name(), "used after it was destroyed");
    return e.info;
  }
  void destroy(std::uint32_t id) {
    Entry& e = find(id);
    if (e.destroyed) throw Error(ErrorKind::InvalidHandle, e.info.name(), "destroyed twice");
    e.destroyed = true;
  }
  bool alive(std::uint32_t id) const {
    const auto it = entries_.find(id);
    return it != entries_.end() && !it->second.destroyed;
  }

 private:
  struct Entry {
    T info;
    bool destroyed = false;
  };
  Entry& find(std::uint32_t id) {
    const auto it = entries_.find(id);
    if (it == entries_.end())
      throw Error(ErrorKind::InvalidHandle, kind_, "handle " + std::to_string(id) + " was never created");
    return it->second;
  }
  std::string kind_;
  std::unordered_map<std::uint32_t, Entry> entries_;
};

struct Objects {
  Table<BufferInfo> buffers{"buffer"};
  Table<ImageInfo> images{"image"};
  Table<PipelineInfo> pipelines{"pipeline"};
  Table<BindingSetInfo> binding_sets{"binding set"};
  Table<AccelInfo> accels{"acceleration structure"};
  Table<TimerInfo> timers{"timer queries"};
  // Submissions so far and how many wait() has seen finish: a list submitted at serial s may
  // still execute while s > completed.
  std::uint64_t submitted = 0;
  std::uint64_t completed = 0;
  const Capabilities* capabilities = nullptr;

  // The debug name of a live resource (InvalidHandle when it is not one).
  const std::string& resource_name(Resource r);
};

// The command list of a validating device (validate_command_list.cpp).
class ValidatingCommandList;
std::unique_ptr<CommandList> make_command_list(Objects& objects, std::unique_ptr<CommandList> inner,
                                               std::string_view name);
// The inner list of one of ours, after the submit-time checks; InvalidUsage for a foreign list.
CommandList& prepare_submit(Objects& objects, CommandList& list);

}  // namespace hal::validate
