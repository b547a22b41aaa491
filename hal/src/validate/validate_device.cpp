// The validating device: checks creation, destruction, binding sets, submission and host
// transfers against the HAL contract, then forwards to the wrapped backend.
#include <string>

#include "hal/layer.hpp"
#include "hal/validate.hpp"
#include "objects.hpp"

namespace hal::validate {
namespace {

// Larger requests are mistakes (a negative size cast to unsigned), not allocation failures.
constexpr std::uint64_t kAbsurdBufferSize = std::uint64_t{1} << 48;

std::string describe(const ShaderBinding& b) {
  return "'" + std::string(b.name) + "' (" + std::string(to_string(b.kind)) + ", set " + std::to_string(b.set) +
         " binding " + std::to_string(b.binding) + ")";
}

const char* resource_kind(ResourceKind kind) {
  switch (kind) {
    case ResourceKind::Buffer:
      return "buffer";
    case ResourceKind::Image:
      return "image";
    case ResourceKind::Accel:
      return "acceleration structure";
  }
  return "resource";
}

class ValidatingDevice final : public Device, public DeviceLayer {
 public:
  explicit ValidatingDevice(std::unique_ptr<Device> inner) : inner_(std::move(inner)) {
    if (!inner_) throw Error(ErrorKind::InvalidUsage, "validate", "wrap() needs a device");
    objects_.capabilities = &inner_->capabilities();
  }
  Device& inner() override { return *inner_; }

  const AdapterInfo& adapter() const override { return inner_->adapter(); }
  const Capabilities& capabilities() const override { return inner_->capabilities(); }

  BufferHandle create_buffer(const BufferDesc& desc) override {
    if (desc.size == 0) throw Error(ErrorKind::InvalidDescriptor, desc.name, "buffer size is 0 bytes");
    if (desc.size >= kAbsurdBufferSize)
      throw Error(ErrorKind::InvalidDescriptor, desc.name,
                  "buffer size " + std::to_string(desc.size) + " bytes is absurd (over 256 TiB)");
    if (desc.usage == BufferUsage::None) throw Error(ErrorKind::InvalidDescriptor, desc.name, "buffer usage is None");
    if (has(desc.usage, BufferUsage::AccelBuildInput) && !capabilities().acceleration_structures)
      throw Error(ErrorKind::Unsupported, desc.name,
                  "usage AccelBuildInput needs acceleration structures, which " + adapter().name + " lacks");
    if (capabilities().max_buffer_size && desc.size > capabilities().max_buffer_size)
      throw Error(ErrorKind::OutOfMemory, desc.name,
                  std::to_string(desc.size) + " bytes exceed the device's largest buffer (" +
                      std::to_string(capabilities().max_buffer_size) + " bytes)");
    const BufferHandle h = inner_->create_buffer(desc);
    objects_.buffers.add(h.id, {desc});
    return h;
  }

  ImageHandle create_image(const ImageDesc& desc) override {
    if (format_size(desc.format) == 0)
      throw Error(ErrorKind::InvalidDescriptor, desc.name,
                  "image format is undefined or unknown (value " + std::to_string(static_cast<int>(desc.format)) + ")");
    const std::uint32_t max = capabilities().max_image_dimension;
    const std::string size = std::to_string(desc.width) + "x" + std::to_string(desc.height);
    if (desc.width == 0 || desc.height == 0)
      throw Error(ErrorKind::InvalidDescriptor, desc.name, "image size " + size + " has a zero side");
    if (max && (desc.width > max || desc.height > max))
      throw Error(ErrorKind::InvalidDescriptor, desc.name,
                  "image size " + size + " exceeds the device's largest 2D image side " + std::to_string(max));
    if (desc.usage == ImageUsage::None) throw Error(ErrorKind::InvalidDescriptor, desc.name, "image usage is None");
    const ImageHandle h = inner_->create_image(desc);
    objects_.images.add(h.id, {desc});
    return h;
  }

  PipelineHandle create_pipeline(const ComputePipelineDesc& desc) override {
    if (!desc.shader) throw Error(ErrorKind::InvalidDescriptor, desc.name, "pipeline has no shader");
    const std::string shader(desc.shader->name);
    if (desc.shader->uses_ray_query && !capabilities().ray_query)
      throw Error(ErrorKind::Unsupported, desc.name,
                  "shader '" + shader + "' uses ray queries, which " + adapter().name + " lacks");
    for (const auto& b : desc.shader->bindings)
      if (b.kind == BindingKind::AccelerationStructure && !capabilities().acceleration_structures)
        throw Error(ErrorKind::Unsupported, desc.name,
                    "shader binding '" + std::string(b.name) + "' is an acceleration structure, which " +
                        adapter().name + " lacks");
    const PipelineHandle h = inner_->create_pipeline(desc);
    objects_.pipelines.add(h.id, {desc.name, desc.shader});
    return h;
  }

  BindingSetHandle create_binding_set(const BindingSetDesc& desc) override {
    const PipelineInfo& pipeline = objects_.pipelines.get(desc.pipeline.id);
    const ShaderInfo& shader = *pipeline.shader;
    const std::string shader_name(shader.name);
    BindingSetInfo info{desc.name, pipeline.shader, std::vector<Resource>(shader.bindings.size())};
    for (const auto& entry : desc.entries) {
      const std::string cpp = "C++ entry '" + entry.name + "' (" + resource_kind(entry.resource.kind) + ")";
      const ShaderBinding* binding = shader.find(entry.name);
      if (!binding) {
        std::string known;
        for (const auto& b : shader.bindings) known += (known.empty() ? "" : ", ") + describe(b);
        throw Error(ErrorKind::BindingMismatch, desc.name,
                    cpp + " names no binding of shader '" + shader_name + "'; the shader has " +
                        (known.empty() ? "no bindings" : known));
      }
      if (binding->kind == BindingKind::UniformBuffer)
        throw Error(ErrorKind::BindingMismatch, desc.name,
                    cpp + " binds shader '" + shader_name + "' uniform block " + describe(*binding) +
                        ", which is bound implicitly from DispatchDesc::uniforms");
      if (!binding_accepts(binding->kind, entry.resource.kind))
        throw Error(ErrorKind::BindingMismatch, desc.name,
                    cpp + " does not match shader '" + shader_name + "' binding " + describe(*binding));
      const auto index = static_cast<std::size_t>(binding - shader.bindings.data());
      if (info.bound[index].id != 0)
        throw Error(ErrorKind::BindingMismatch, desc.name,
                    cpp + " binds shader '" + shader_name + "' binding " + describe(*binding) + " a second time");
      check_bound_resource(desc.name, cpp, shader_name, *binding, entry.resource);
      info.bound[index] = entry.resource;
    }
    const BindingSetHandle h = inner_->create_binding_set(desc);
    objects_.binding_sets.add(h.id, std::move(info));
    return h;
  }

  AccelHandle create_blas(const BlasDesc& desc) override {
    require_accels(desc.name);
    auto input = [&](BufferHandle handle, std::uint64_t bytes, const char* what, std::uint32_t count) {
      const BufferInfo& b = objects_.buffers.get(handle.id);
      if (b.desc.size < bytes)
        throw Error(ErrorKind::InvalidDescriptor, desc.name,
                    std::string(what) + " buffer '" + b.name() + "' is smaller than " + std::to_string(count) +
                        " entries (" + std::to_string(bytes) + " bytes)");
      if (!has(b.desc.usage, BufferUsage::AccelBuildInput))
        throw Error(ErrorKind::InvalidUsage, b.name(), "input of BLAS '" + desc.name + "' needs AccelBuildInput usage");
    };
    if (desc.geometry == BlasGeometry::Boxes) {
      if (desc.box_count == 0)
        throw Error(ErrorKind::InvalidDescriptor, desc.name, "BLAS of boxes needs at least one box");
      input(desc.boxes, std::uint64_t{desc.box_count} * 24, "box", desc.box_count);
    } else {
      if (desc.vertex_count == 0 || desc.triangle_count == 0)
        throw Error(ErrorKind::InvalidDescriptor, desc.name,
                    "BLAS needs at least one vertex and one triangle (got " + std::to_string(desc.vertex_count) +
                        " vertices, " + std::to_string(desc.triangle_count) + " triangles)");
      input(desc.vertices, std::uint64_t{desc.vertex_count} * 12, "vertex", desc.vertex_count);
      input(desc.indices, std::uint64_t{desc.triangle_count} * 12, "index", desc.triangle_count);
    }
    const AccelHandle h = inner_->create_blas(desc);
    AccelInfo info;
    info.label = desc.name;
    info.blas = desc;
    objects_.accels.add(h.id, std::move(info));
    return h;
  }

  AccelHandle create_tlas(const TlasDesc& desc) override {
    require_accels(desc.name);
    if (desc.max_instances == 0 || desc.max_instances > (1u << 24))
      throw Error(ErrorKind::InvalidDescriptor, desc.name,
                  "TLAS max_instances " + std::to_string(desc.max_instances) + " is not in 1..16777216");
    const AccelHandle h = inner_->create_tlas(desc);
    AccelInfo info;
    info.label = desc.name;
    info.top = true;
    info.tlas = desc;
    objects_.accels.add(h.id, std::move(info));
    return h;
  }

  TimerQueriesHandle create_timer_queries(const TimerQueriesDesc& desc) override {
    if (desc.regions == 0 || desc.regions > 65536)
      throw Error(ErrorKind::InvalidDescriptor, desc.name,
                  "timer regions " + std::to_string(desc.regions) + " is not in 1..65536");
    const TimerQueriesHandle h = inner_->create_timer_queries(desc);
    objects_.timers.add(h.id, {desc});
    return h;
  }

  std::unique_ptr<CommandList> create_command_list(std::string_view name) override {
    return make_command_list(objects_, inner_->create_command_list(name), name);
  }

  void destroy(BufferHandle h) override { destroy(objects_.buffers, h); }
  void destroy(ImageHandle h) override { destroy(objects_.images, h); }
  void destroy(PipelineHandle h) override { destroy(objects_.pipelines, h); }
  void destroy(BindingSetHandle h) override { destroy(objects_.binding_sets, h); }
  void destroy(AccelHandle h) override { destroy(objects_.accels, h); }
  void destroy(TimerQueriesHandle h) override { destroy(objects_.timers, h); }

  void submit(CommandList& commands) override {
    CommandList& inner = prepare_submit(objects_, commands);
    inner_->submit(inner);
  }
  void wait() override {
    inner_->wait();
    objects_.completed = objects_.submitted;
  }

  void upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) override {
    check_range(objects_.buffers.get(dst.id), BufferUsage::CopyDst, "upload_buffer", "upload", offset, data.size());
    inner_->upload_buffer(dst, offset, data);
  }
  void read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) override {
    check_range(objects_.buffers.get(src.id), BufferUsage::CopySrc, "read_buffer", "read", offset, out.size());
    inner_->read_buffer(src, offset, out);
  }
  void upload_image(ImageHandle dst, std::span<const std::byte> data) override {
    check_whole(objects_.images.get(dst.id), ImageUsage::CopyDst, "upload_image", "got", data.size());
    inner_->upload_image(dst, data);
  }
  void read_image(ImageHandle src, std::span<std::byte> out) override {
    check_whole(objects_.images.get(src.id), ImageUsage::CopySrc, "read_image", "got room for", out.size());
    inner_->read_image(src, out);
  }
  std::optional<std::uint64_t> device_memory_bytes() const override { return inner_->device_memory_bytes(); }
  std::vector<std::optional<double>> read_timers(TimerQueriesHandle timers) override {
    objects_.timers.get(timers.id);
    return inner_->read_timers(timers);
  }

 private:
  template <typename T, typename H>
  void destroy(Table<T>& table, H handle) {
    table.get(handle.id);  // throws for unknown and already destroyed handles
    inner_->destroy(handle);
    table.destroy(handle.id);
  }

  void require_accels(const std::string& name) {
    if (!capabilities().acceleration_structures)
      throw Error(ErrorKind::Unsupported, name, "acceleration structures are not supported by " + adapter().name);
  }

  // Usage, format, level and size of a resource bound to a (non-uniform) binding of a set.
  void check_bound_resource(const std::string& set, const std::string& cpp, const std::string& shader,
                            const ShaderBinding& binding, Resource resource) {
    switch (resource.kind) {
      case ResourceKind::Buffer: {
        const BufferInfo& b = objects_.buffers.get(resource.id);
        if (!has(b.desc.usage, BufferUsage::Storage))
          throw Error(ErrorKind::InvalidUsage, b.name(),
                      "bound to storage binding " + describe(binding) + " of set '" + set +
                          "' but created without Storage usage");
        const std::uint64_t range = capabilities().max_storage_buffer_range;
        if (range && b.desc.size > range)
          throw Error(ErrorKind::InvalidUsage, b.name(),
                      "is " + std::to_string(b.desc.size) +
                          " bytes, larger than the device's largest storage binding (" + std::to_string(range) +
                          " bytes)");
        return;
      }
      case ResourceKind::Image: {
        const ImageInfo& i = objects_.images.get(resource.id);
        const bool storage = binding.kind == BindingKind::StorageImage;
        if (!has(i.desc.usage, storage ? ImageUsage::Storage : ImageUsage::Sampled))
          throw Error(ErrorKind::InvalidUsage, i.name(),
                      "bound to " + describe(binding) + " of set '" + set + "' but created without " +
                          (storage ? "Storage" : "Sampled") + " usage");
        if (storage && binding.format != Format::Undefined && binding.format != i.desc.format)
          throw Error(ErrorKind::BindingMismatch, set,
                      cpp + " is image '" + i.name() + "' of format " + std::string(format_name(i.desc.format)) +
                          " but shader '" + shader + "' binding " + describe(binding) + " is declared " +
                          std::string(format_name(binding.format)));
        return;
      }
      case ResourceKind::Accel: {
        const AccelInfo& a = objects_.accels.get(resource.id);
        if (!a.top)
          throw Error(ErrorKind::BindingMismatch, set,
                      cpp + " is bottom-level structure '" + a.name() + "' but shader '" + shader + "' binding " +
                          describe(binding) + " traces a top-level one");
        return;
      }
    }
  }

  static void check_range(const BufferInfo& b, BufferUsage usage, const char* call, const char* what,
                          std::uint64_t offset, std::uint64_t size) {
    if (!has(b.desc.usage, usage))
      throw Error(ErrorKind::InvalidUsage, b.name(),
                  std::string(call) + " needs a buffer created with " +
                      (usage == BufferUsage::CopyDst ? "CopyDst" : "CopySrc") + " usage");
    if (offset > b.desc.size || size > b.desc.size - offset)
      throw Error(ErrorKind::InvalidUsage, b.name(),
                  std::string(what) + " of " + std::to_string(size) + " bytes at offset " + std::to_string(offset) +
                      " runs past the end of the " + std::to_string(b.desc.size) + "-byte buffer");
  }
  static void check_whole(const ImageInfo& i, ImageUsage usage, const char* call, const char* got, std::uint64_t size) {
    if (!has(i.desc.usage, usage))
      throw Error(ErrorKind::InvalidUsage, i.name(),
                  std::string(call) + " needs an image created with " +
                      (usage == ImageUsage::CopyDst ? "CopyDst" : "CopySrc") + " usage");
    if (size != i.bytes())
      throw Error(ErrorKind::InvalidUsage, i.name(),
                  std::string(call) + " " + got + " " + std::to_string(size) + " bytes; the image holds " +
                      std::to_string(i.bytes()));
  }

  std::unique_ptr<Device> inner_;
  Objects objects_;
};

}  // namespace

const std::string& Objects::resource_name(Resource r) {
  switch (r.kind) {
    case ResourceKind::Buffer:
      return buffers.get(r.id).name();
    case ResourceKind::Image:
      return images.get(r.id).name();
    case ResourceKind::Accel:
      return accels.get(r.id).name();
  }
  throw Error(ErrorKind::InvalidHandle, "resource", "unknown resource kind");
}

bool binding_accepts(BindingKind kind, ResourceKind resource) {
  switch (kind) {
    case BindingKind::StorageBuffer:
      return resource == ResourceKind::Buffer;
    case BindingKind::SampledImage:
    case BindingKind::StorageImage:
      return resource == ResourceKind::Image;
    case BindingKind::AccelerationStructure:
      return resource == ResourceKind::Accel;
    case BindingKind::UniformBuffer:
      return false;  // bound implicitly from DispatchDesc::uniforms
  }
  return false;
}

std::unique_ptr<Device> wrap(std::unique_ptr<Device> inner) {
  return std::make_unique<ValidatingDevice>(std::move(inner));
}

}  // namespace hal::validate
