// hal/command_list.hpp: recording GPU work.
//
// A CommandList is created by a Device, recorded on one thread, submitted with Device::submit and
// may be recorded again after the device has finished it (Device::wait). Recording validates its
// arguments and throws hal::Error for a bad handle or a call that breaks the contract; hazards
// (a missing barrier) are not detected here on real backends: the recording HAL finds them.
//
// Barriers are explicit: before a resource is used in a new way, record barrier({res, before,
// after}). `before` must be the state the resource is in; dispatches need ShaderRead for bindings
// the shader only reads and ShaderWrite for bindings it writes; copies need CopySrc/CopyDst.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string_view>

#include "hal/types.hpp"

namespace hal {

struct Barrier {
  Resource resource;
  State before = State::Undefined;  // Undefined: nothing to wait for, contents discarded
  State after = State::Undefined;
  // The contents need not be kept (a transient's memory handed to another resource). The barrier
  // still waits for the earlier uses in `before`; a barrier from Undefined does not.
  bool discard = false;
};

struct DispatchDesc {
  PipelineHandle pipeline;
  BindingSetHandle bindings;
  // Contents of the shader's uniform block (copied at record time); size must equal the
  // reflection's uniform_block_size, or be empty when the shader has none.
  std::span<const std::byte> uniforms;
  std::uint32_t groups_x = 1, groups_y = 1, groups_z = 1;
};

struct BufferCopy {
  BufferHandle src, dst;
  std::uint64_t src_offset = 0, dst_offset = 0, size = 0;
};

class CommandList {
 public:
  virtual ~CommandList() = default;
  CommandList() = default;
  CommandList(const CommandList&) = delete;
  CommandList& operator=(const CommandList&) = delete;

  // Starts a fresh recording: drops whatever was recorded before. The device must be done with it.
  virtual void reset() = 0;

  // Debug labels name the commands between them in captures, errors and hazard reports.
  virtual void begin_label(std::string_view label) = 0;
  virtual void end_label() = 0;

  virtual void barrier(std::span<const Barrier> barriers) = 0;
  void barrier(const Barrier& b) { barrier(std::span<const Barrier>(&b, 1)); }
  void barrier(std::initializer_list<Barrier> list) { barrier(std::span<const Barrier>(list.begin(), list.size())); }

  virtual void dispatch(const DispatchDesc& desc) = 0;

  virtual void copy_buffer(const BufferCopy& copy) = 0;
  // Whole-image copy; both images have the same size and format.
  virtual void copy_image(ImageHandle src, ImageHandle dst) = 0;
  // Tightly packed rows, whole image.
  virtual void copy_buffer_to_image(BufferHandle src, ImageHandle dst) = 0;
  virtual void copy_image_to_buffer(ImageHandle src, BufferHandle dst) = 0;
  // Fills with a repeated 32-bit word; the buffer must be in CopyDst.
  virtual void clear_buffer(BufferHandle buffer, std::uint32_t word) = 0;
  // Every texel set to `value` (converted to the format); the image must be in CopyDst.
  virtual void clear_image(ImageHandle image, std::array<float, 4> value) = 0;

  // Builds (or, with update, refits) a bottom-level structure from its descriptor's buffers,
  // which must be in AccelBuildInput; the structure must be in AccelWrite.
  virtual void build_blas(AccelHandle blas, bool update) = 0;
  // Builds a top-level structure over instances (copied at record time); every referenced BLAS
  // must be in AccelRead, the TLAS in AccelWrite.
  virtual void build_tlas(AccelHandle tlas, std::span<const TlasInstance> instances, bool update) = 0;

  // GPU time of a region: begin_timer and end_timer around the commands to be timed.
  virtual void begin_timer(TimerQueriesHandle timers, std::uint32_t region) = 0;
  virtual void end_timer(TimerQueriesHandle timers, std::uint32_t region) = 0;
};

}  // namespace hal
