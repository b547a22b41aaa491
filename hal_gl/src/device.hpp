// The OpenGL device: object tables, the context, and the operations command lists replay.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "context.hpp"
#include "formats.hpp"
#include "gpu_clear.hpp"
#include "hal/device.hpp"
#include "hal/error.hpp"

namespace hal::gl {

struct BufferObject {
  BufferDesc desc;
  GLuint buffer = 0;
};
struct ImageObject {
  ImageDesc desc;
  GLuint texture = 0;
  GlFormat format;
};
struct PipelineObject {
  std::string name;
  const ShaderInfo* shader = nullptr;
  GLuint program = 0;
};
struct BindingSetObject {
  std::string name;
  const ShaderInfo* shader = nullptr;
  std::vector<Resource> bound;  // parallel to shader->bindings
};
struct TimerObject {
  std::string name;
  std::vector<GLuint> queries;  // two per region: begin, end
  std::vector<bool> written;    // region recorded by a submitted list
};

// Objects by handle id; ids are never reused.
template <typename T>
class Table {
 public:
  std::uint32_t add(T object) {
    objects_.emplace(next_, std::move(object));
    return next_++;
  }
  T& get(std::uint32_t id, const char* kind) {
    const auto it = objects_.find(id);
    if (it == objects_.end())
      throw Error(ErrorKind::InvalidHandle, kind, "handle " + std::to_string(id) + " is not a live object");
    return it->second;
  }
  T take(std::uint32_t id, const char* kind) {
    T object = std::move(get(id, kind));
    objects_.erase(id);
    return object;
  }
  std::unordered_map<std::uint32_t, T>& all() { return objects_; }

 private:
  std::uint32_t next_ = 1;
  std::unordered_map<std::uint32_t, T> objects_;
};

class GlDevice final : public Device {
 public:
  explicit GlDevice(const DeviceOptions& options);
  ~GlDevice() override;

  const AdapterInfo& adapter() const override { return adapter_; }
  const Capabilities& capabilities() const override { return capabilities_; }
  BufferHandle create_buffer(const BufferDesc& desc) override;
  ImageHandle create_image(const ImageDesc& desc) override;
  PipelineHandle create_pipeline(const ComputePipelineDesc& desc) override;
  BindingSetHandle create_binding_set(const BindingSetDesc& desc) override;
  AccelHandle create_blas(const BlasDesc& desc) override;
  AccelHandle create_tlas(const TlasDesc& desc) override;
  TimerQueriesHandle create_timer_queries(const TimerQueriesDesc& desc) override;
  std::unique_ptr<CommandList> create_command_list(std::string_view name) override;
  void destroy(BufferHandle handle) override;
  void destroy(ImageHandle handle) override;
  void destroy(PipelineHandle handle) override;
  void destroy(BindingSetHandle handle) override;
  void destroy(AccelHandle handle) override;
  void destroy(TimerQueriesHandle handle) override;
  void submit(CommandList& commands) override;
  void wait() override;
  void upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) override;
  void read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) override;
  void upload_image(ImageHandle dst, std::span<const std::byte> data) override;
  void read_image(ImageHandle src, std::span<std::byte> out) override;
  std::vector<std::optional<double>> read_timers(TimerQueriesHandle timers) override;

  // What replayed commands do (command_list.cpp records closures over these).
  void make_current() const { context_.make_current(); }
  bool debug_groups() const { return debug_output_; }          // KHR_debug: labels become debug groups
  void check_gl(const std::string& object, const char* what);  // throws on a GL error
  void memory_barrier(State before, State after);
  void dispatch(PipelineHandle pipeline, BindingSetHandle set, const std::vector<std::byte>& uniforms, std::uint32_t x,
                std::uint32_t y, std::uint32_t z);
  void copy_buffer(const BufferCopy& copy);
  void copy_image(ImageHandle src, ImageHandle dst);
  void copy_buffer_to_image(BufferHandle src, ImageHandle dst);
  void copy_image_to_buffer(ImageHandle src, BufferHandle dst);
  void clear_buffer(BufferHandle buffer, std::uint32_t word);
  void clear_image(ImageHandle image, std::array<float, 4> value);
  GpuClear& gpu_clear();
  void timestamp(TimerQueriesHandle timers, std::uint32_t query);
  // Reads a whole image into `pack` (a bound GL_PIXEL_PACK_BUFFER offset) or host memory.
  void read_texture(const ImageObject& image, void* destination);
  // hal::gl::present: blits `image` to the adopted context's default framebuffer (present.cpp).
  void present(ImageHandle image, std::uint32_t width, std::uint32_t height);

 private:
  DeviceOptions options_;
  Context context_;
  AdapterInfo adapter_;
  Capabilities capabilities_;
  GLuint uniform_buffer_ = 0;            // refilled (orphaned) for every dispatch's uniform block
  GLuint read_framebuffer_ = 0;          // OpenGL ES reads images back through it
  std::unique_ptr<GpuClear> gpu_clear_;  // buffer clears (and ES's image clears) on the GPU, made at the first clear
  // Programs from the shader tool's OpenGL SPIR-V ("spirv-gl") instead of its GLSL.
  bool spirv_shaders_ = false;
  // Buffers with immutable storage (glBufferStorage: OpenGL 4.4+, ES with GL_EXT_buffer_storage):
  // copies through NVIDIA's glBufferData(GL_DYNAMIC_COPY) buffers ran at 0.95-2.4 TB/s at some
  // sizes where these ran at Vulkan's 2.8-3.7 (docs/performance.md).
  bool immutable_buffers_ = false;
  // read_buffer copies into this and maps it, never the buffer the passes use: NVIDIA's driver may
  // move a buffer that is mapped for reading into system memory, where every atomic the passes do
  // on it crosses the bus.
  GLuint readback_buffer_ = 0;
  std::uint64_t readback_size_ = 0;
  bool debug_output_ = false;
  Table<BufferObject> buffers_;
  Table<ImageObject> images_;
  Table<PipelineObject> pipelines_;
  Table<BindingSetObject> binding_sets_;
  Table<TimerObject> timers_;
};

}  // namespace hal::gl
