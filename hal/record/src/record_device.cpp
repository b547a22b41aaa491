// The recording device: object creation and destruction, submission, host transfers.
#include <algorithm>
#include <string>

#include "impl.hpp"

namespace hal::record {
namespace {

constexpr std::uint64_t kMaxBufferSize = std::uint64_t(1) << 32;  // a plausible device limit (4 GiB)

template <typename T>
std::uint32_t add(std::vector<T>& table, T object) {
  table.push_back(std::move(object));
  return static_cast<std::uint32_t>(table.size());
}

template <typename T>
void mark_destroyed(T& object, std::string_view name) {
  if (object.destroyed) throw Error(ErrorKind::InvalidHandle, name, "destroyed twice");
  object.destroyed = true;
}

bool kind_matches(BindingKind kind, ResourceKind resource) {
  switch (kind) {
    case BindingKind::UniformBuffer:
    case BindingKind::StorageBuffer: return resource == ResourceKind::Buffer;
    case BindingKind::SampledImage:
    case BindingKind::StorageImage: return resource == ResourceKind::Image;
    case BindingKind::AccelerationStructure: return resource == ResourceKind::Accel;
  }
  return false;
}

std::string_view resource_kind_name(ResourceKind kind) {
  switch (kind) {
    case ResourceKind::Buffer: return "buffer";
    case ResourceKind::Image: return "image";
    case ResourceKind::Accel: return "acceleration structure";
  }
  return "?";
}

}  // namespace

Capabilities RecordOptions::default_capabilities() {
  Capabilities c;
  c.ray_query = true;
  c.acceleration_structures = true;
  c.fp16_storage = true;
  c.timestamps = false;  // nothing executes, so there is nothing to time
  c.subgroup_size = 32;
  c.max_image_dimension = 16384;
  c.max_storage_buffer_range = kMaxBufferSize;
  c.max_buffer_size = kMaxBufferSize;
  return c;
}

std::string_view to_string(ReportKind kind) {
  switch (kind) {
    case ReportKind::ReadAfterWrite: return "read-after-write";
    case ReportKind::WriteAfterRead: return "write-after-read";
    case ReportKind::WriteAfterWrite: return "write-after-write";
    case ReportKind::BarrierStateMismatch: return "barrier-state-mismatch";
    case ReportKind::WrongState: return "wrong-state";
    case ReportKind::UseOfDestroyed: return "use-of-destroyed";
    case ReportKind::ReadBeforeWrite: return "read-before-write";
    case ReportKind::UnboundBinding: return "unbound-binding";
    case ReportKind::UsageMismatch: return "usage-mismatch";
  }
  return "?";
}

void RecordDevice::Impl::check_exists(Resource r) {
  switch (r.kind) {
    case ResourceKind::Buffer: buffer(BufferHandle{r.id}); break;
    case ResourceKind::Image: image(ImageHandle{r.id}); break;
    case ResourceKind::Accel: accel(AccelHandle{r.id}); break;
  }
}

std::string RecordDevice::Impl::name_of(Resource r) const {
  switch (r.kind) {
    case ResourceKind::Buffer: return buffers.at(r.id - 1).desc.name;
    case ResourceKind::Image: return images.at(r.id - 1).desc.name;
    case ResourceKind::Accel: return accels.at(r.id - 1).name;
  }
  return "?";
}

bool RecordDevice::Impl::destroyed(Resource r) const {
  switch (r.kind) {
    case ResourceKind::Buffer: return buffers.at(r.id - 1).destroyed;
    case ResourceKind::Image: return images.at(r.id - 1).destroyed;
    case ResourceKind::Accel: return accels.at(r.id - 1).destroyed;
  }
  return true;
}

RecordDevice::RecordDevice(RecordOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  impl_->adapter = {"recording HAL", "hal::record (no GPU)", "recording", DeviceType::NoGpu};
}
RecordDevice::~RecordDevice() = default;

const std::vector<Report>& RecordDevice::reports() const { return impl_->reports; }
void RecordDevice::clear_reports() { impl_->reports.clear(); }
const std::vector<LogEntry>& RecordDevice::log() const { return impl_->log; }
std::string RecordDevice::log_text() const {
  std::string text;
  for (const auto& e : impl_->log) text += e.text + "\n";
  return text;
}
State RecordDevice::state_of(Resource resource) const {
  impl_->check_exists(resource);
  return impl_->track(resource).state;
}
std::string RecordDevice::name_of(Resource resource) const {
  impl_->check_exists(resource);
  return impl_->name_of(resource);
}

const AdapterInfo& RecordDevice::adapter() const { return impl_->adapter; }
const Capabilities& RecordDevice::capabilities() const { return impl_->options.capabilities; }

BufferHandle RecordDevice::create_buffer(const BufferDesc& desc) {
  if (desc.size == 0) throw Error(ErrorKind::InvalidDescriptor, desc.name, "buffer size is zero");
  if (desc.size > capabilities().max_buffer_size)
    throw Error(ErrorKind::OutOfMemory, desc.name,
                std::to_string(desc.size) + " bytes exceed the device limit of " +
                    std::to_string(capabilities().max_buffer_size));
  if (desc.usage == BufferUsage::None) throw Error(ErrorKind::InvalidDescriptor, desc.name, "buffer has no usage");
  return BufferHandle{add(impl_->buffers, BufferObject{desc})};
}

ImageHandle RecordDevice::create_image(const ImageDesc& desc) {
  if (desc.format == Format::Undefined) throw Error(ErrorKind::InvalidDescriptor, desc.name, "image format is undefined");
  const auto max = capabilities().max_image_dimension;
  if (desc.width == 0 || desc.height == 0 || desc.width > max || desc.height > max)
    throw Error(ErrorKind::InvalidDescriptor, desc.name,
                "image size " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                    " is outside 1.." + std::to_string(max));
  if (desc.usage == ImageUsage::None) throw Error(ErrorKind::InvalidDescriptor, desc.name, "image has no usage");
  return ImageHandle{add(impl_->images, ImageObject{desc})};
}

PipelineHandle RecordDevice::create_pipeline(const ComputePipelineDesc& desc) {
  if (!desc.shader) throw Error(ErrorKind::InvalidDescriptor, desc.name, "pipeline has no shader");
  if (desc.shader->uses_ray_query && !capabilities().ray_query)
    throw Error(ErrorKind::Unsupported, desc.name,
                "shader '" + std::string(desc.shader->name) + "' uses ray queries, which the device lacks");
  for (const auto& s : desc.specializations) {
    bool found = false;
    for (const auto& c : desc.shader->spec_constants) found = found || c.name == s.name;
    if (!found)
      throw Error(ErrorKind::BindingMismatch, desc.name,
                  "specialization '" + s.name + "' is not a constant of shader '" + std::string(desc.shader->name) + "'");
  }
  return PipelineHandle{add(impl_->pipelines, PipelineObject{desc.name, desc.shader})};
}

BindingSetHandle RecordDevice::create_binding_set(const BindingSetDesc& desc) {
  auto& pipeline = impl_->pipeline(desc.pipeline);
  const ShaderInfo& shader = *pipeline.shader;
  BindingSetObject set{desc.name, desc.pipeline, std::vector<std::optional<Resource>>(shader.bindings.size())};
  for (const auto& entry : desc.entries) {
    impl_->check_exists(entry.resource);
    const ShaderBinding* b = shader.find(entry.name);
    if (!b || b->kind == BindingKind::UniformBuffer)
      throw Error(ErrorKind::BindingMismatch, desc.name,
                  "C++ binds '" + entry.name + "' but shader '" + std::string(shader.name) + "' has no such binding");
    if (!kind_matches(b->kind, entry.resource.kind))
      throw Error(ErrorKind::BindingMismatch, desc.name,
                  "C++ binds " + std::string(resource_kind_name(entry.resource.kind)) + " '" +
                      impl_->name_of(entry.resource) + "' to '" + entry.name + "', which shader '" +
                      std::string(shader.name) + "' declares as " + std::string(to_string(b->kind)));
    bool usage_ok = true;
    if (entry.resource.kind == ResourceKind::Buffer)
      usage_ok = has(impl_->buffers[entry.resource.id - 1].desc.usage, BufferUsage::Storage);
    if (entry.resource.kind == ResourceKind::Image)
      usage_ok = has(impl_->images[entry.resource.id - 1].desc.usage,
                     b->kind == BindingKind::StorageImage ? ImageUsage::Storage : ImageUsage::Sampled);
    if (!usage_ok) {
      const std::string name = impl_->name_of(entry.resource);
      impl_->report(ReportKind::UsageMismatch, name, "", "binding set '" + desc.name + "'",
                    "binding set '" + desc.name + "' binds '" + name + "' as " + std::string(to_string(b->kind)) +
                        " '" + entry.name + "' but it was not created with that usage");
    }
    set.bound[static_cast<std::size_t>(b - shader.bindings.data())] = entry.resource;
  }
  return BindingSetHandle{add(impl_->binding_sets, std::move(set))};
}

AccelHandle RecordDevice::create_blas(const BlasDesc& desc) {
  if (desc.geometry == BlasGeometry::Boxes) {
    impl_->buffer(desc.boxes);
    if (desc.box_count == 0) throw Error(ErrorKind::InvalidDescriptor, desc.name, "bottom-level structure has no boxes");
  } else {
    impl_->buffer(desc.vertices);
    impl_->buffer(desc.indices);
    if (desc.triangle_count == 0 || desc.vertex_count == 0)
      throw Error(ErrorKind::InvalidDescriptor, desc.name, "bottom-level structure has no triangles");
  }
  AccelObject a{desc.name, false, desc};
  return AccelHandle{add(impl_->accels, std::move(a))};
}

AccelHandle RecordDevice::create_tlas(const TlasDesc& desc) {
  if (desc.max_instances == 0) throw Error(ErrorKind::InvalidDescriptor, desc.name, "top-level structure holds no instances");
  return AccelHandle{add(impl_->accels, AccelObject{desc.name, true, {}})};
}

TimerQueriesHandle RecordDevice::create_timer_queries(const TimerQueriesDesc& desc) {
  if (desc.regions == 0) throw Error(ErrorKind::InvalidDescriptor, desc.name, "zero timer regions");
  return TimerQueriesHandle{add(impl_->timers, TimerObject{desc})};
}

std::unique_ptr<CommandList> RecordDevice::create_command_list(std::string_view name) {
  return make_record_command_list(*impl_, name);
}

void RecordDevice::destroy(BufferHandle h) { mark_destroyed(impl_->buffer(h), impl_->buffer(h).desc.name); }
void RecordDevice::destroy(ImageHandle h) { mark_destroyed(impl_->image(h), impl_->image(h).desc.name); }
void RecordDevice::destroy(PipelineHandle h) { mark_destroyed(impl_->pipeline(h), impl_->pipeline(h).name); }
void RecordDevice::destroy(BindingSetHandle h) { mark_destroyed(impl_->binding_set(h), impl_->binding_set(h).name); }
void RecordDevice::destroy(AccelHandle h) { mark_destroyed(impl_->accel(h), impl_->accel(h).name); }
void RecordDevice::destroy(TimerQueriesHandle h) { mark_destroyed(impl_->timer(h), impl_->timer(h).desc.name); }

void RecordDevice::submit(CommandList& commands) {
  for (Command& c : recorded_commands(commands)) impl_->replay(c);
}

void RecordDevice::wait() {}

void RecordDevice::upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) {
  auto& b = impl_->buffer(dst);
  if (offset + data.size() > b.desc.size)
    throw Error(ErrorKind::InvalidUsage, b.desc.name, "upload range is out of bounds");
  impl_->host_access(dst, true, "upload");
}
void RecordDevice::read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) {
  auto& b = impl_->buffer(src);
  if (offset + out.size() > b.desc.size) throw Error(ErrorKind::InvalidUsage, b.desc.name, "read range is out of bounds");
  impl_->host_access(src, false, "readback");
  std::fill(out.begin(), out.end(), std::byte{0});
}
void RecordDevice::upload_image(ImageHandle dst, std::span<const std::byte> data) {
  auto& i = impl_->image(dst);
  if (data.size() != std::uint64_t(i.desc.width) * i.desc.height * format_size(i.desc.format))
    throw Error(ErrorKind::InvalidUsage, i.desc.name, "upload size does not match the image");
  impl_->host_access(dst, true, "upload");
}
void RecordDevice::read_image(ImageHandle src, std::span<std::byte> out) {
  auto& i = impl_->image(src);
  if (out.size() != std::uint64_t(i.desc.width) * i.desc.height * format_size(i.desc.format))
    throw Error(ErrorKind::InvalidUsage, i.desc.name, "readback size does not match the image");
  impl_->host_access(src, false, "readback");
  std::fill(out.begin(), out.end(), std::byte{0});
}

std::vector<std::optional<double>> RecordDevice::read_timers(TimerQueriesHandle timers) {
  return std::vector<std::optional<double>>(impl_->timer(timers).desc.regions);  // unavailable, never zero
}

}  // namespace hal::record
