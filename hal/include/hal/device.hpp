// hal/device.hpp: the device: capabilities, object creation, submission and host transfers.
//
// Thread safety: a Device and the objects it creates are externally synchronised: call them from
// one thread at a time. Ownership: the Device owns every object it creates, named by handles
// (hal/types.hpp); destroy(handle) releases one at once, so the caller must make sure the GPU is
// done with it (wait()). Destroying the Device releases everything.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hal/command_list.hpp"
#include "hal/shader.hpp"
#include "hal/types.hpp"

namespace hal {

enum class DeviceType : std::uint8_t { Other, IntegratedGpu, DiscreteGpu, VirtualGpu, Cpu, NoGpu };
std::string_view to_string(DeviceType type);

// What the device can do. The pipeline picks shader variants from these, never assumes them.
struct Capabilities {
  bool ray_query = false;               // GL_EXT_ray_query in compute shaders
  bool acceleration_structures = false;  // BLAS/TLAS builds (needed by ray queries)
  bool fp16_storage = false;            // 16-bit values in storage buffers
  bool timestamps = false;              // begin_timer/end_timer produce times
  std::uint32_t subgroup_size = 0;      // 0: unknown
  std::uint32_t max_image_dimension = 0;
  std::uint64_t max_storage_buffer_range = 0;
  std::uint64_t max_buffer_size = 0;
};

struct AdapterInfo {
  std::string name;         // "llvmpipe (LLVM 15.0.6, 256 bits)", "NVIDIA H200", ...
  std::string driver;       // driver name and version as the backend reports them
  std::string api_version;  // "Vulkan 1.4.305", "recording", ...
  DeviceType type = DeviceType::Other;
};

struct ComputePipelineDesc {
  std::string name;
  const ShaderInfo* shader = nullptr;
};

struct BindingSetDesc {
  std::string name;
  PipelineHandle pipeline;
  struct Entry {
    std::string name;  // a binding name of the pipeline's shader
    Resource resource;
  };
  std::vector<Entry> entries;  // the uniform block is bound implicitly; list every other binding
};

class Device {
 public:
  virtual ~Device() = default;
  Device() = default;
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  virtual const AdapterInfo& adapter() const = 0;
  virtual const Capabilities& capabilities() const = 0;

  // Creation throws InvalidDescriptor for zero or absurd sizes and unknown formats, Unsupported
  // for a format or feature the device lacks, OutOfMemory when allocation fails.
  virtual BufferHandle create_buffer(const BufferDesc& desc) = 0;
  virtual ImageHandle create_image(const ImageDesc& desc) = 0;
  // Checks the shader's reflection against the device: a ray-query
  // shader on a device without ray queries is Unsupported.
  virtual PipelineHandle create_pipeline(const ComputePipelineDesc& desc) = 0;
  // Every entry must name a binding of the pipeline's shader with a matching kind (buffer,
  // image, accel), else BindingMismatch naming both sides. Bindings left out are reported when
  // a dispatch uses the set.
  virtual BindingSetHandle create_binding_set(const BindingSetDesc& desc) = 0;
  virtual AccelHandle create_blas(const BlasDesc& desc) = 0;
  virtual AccelHandle create_tlas(const TlasDesc& desc) = 0;
  virtual TimerQueriesHandle create_timer_queries(const TimerQueriesDesc& desc) = 0;
  virtual std::unique_ptr<CommandList> create_command_list(std::string_view name) = 0;

  virtual void destroy(BufferHandle handle) = 0;
  virtual void destroy(ImageHandle handle) = 0;
  virtual void destroy(PipelineHandle handle) = 0;
  virtual void destroy(BindingSetHandle handle) = 0;
  virtual void destroy(AccelHandle handle) = 0;
  virtual void destroy(TimerQueriesHandle handle) = 0;

  // Queues the recorded commands. The command list must not be reset before wait() returns.
  virtual void submit(CommandList& commands) = 0;
  // Blocks until all submitted work is done. Throws DeviceLost if the device was lost.
  virtual void wait() = 0;

  // Synchronous host transfers, outside any command list (the device stages and waits).
  // An upload leaves the resource in CopyDst; a readback needs it in CopySrc and keeps it there.
  virtual void upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) = 0;
  virtual void read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) = 0;
  // Whole image, tightly packed rows of format_size(format) * width bytes.
  virtual void upload_image(ImageHandle dst, std::span<const std::byte> data) = 0;
  virtual void read_image(ImageHandle src, std::span<std::byte> out) = 0;

  // GPU milliseconds of each region of the last submitted use of `timers` (after wait()).
  // An entry is empty when the device has no timestamps or the region was not recorded: a
  // missing time is never reported as zero.
  virtual std::vector<std::optional<double>> read_timers(TimerQueriesHandle timers) = 0;

  // Bytes of device memory the backend holds now (memory blocks and dedicated allocations, not the
  // resources in them), for leak checks over long runs; empty when the backend cannot say.
  virtual std::optional<std::uint64_t> device_memory_bytes() const { return std::nullopt; }
};

}  // namespace hal
