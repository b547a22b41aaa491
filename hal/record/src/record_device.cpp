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
  return BufferHandle{add(impl_->buffers, BufferObject{desc})};
}

ImageHandle RecordDevice::create_image(const ImageDesc& desc) {
  return ImageHandle{add(impl_->images, ImageObject{desc})};
}

PipelineHandle RecordDevice::create_pipeline(const ComputePipelineDesc& desc) {
  return PipelineHandle{add(impl_->pipelines, PipelineObject{desc.name, desc.shader})};
}

BindingSetHandle RecordDevice::create_binding_set(const BindingSetDesc& desc) {
  const ShaderInfo& shader = *impl_->pipeline(desc.pipeline).shader;
  BindingSetObject set{desc.name, desc.pipeline, std::vector<std::optional<Resource>>(shader.bindings.size())};
  for (const auto& entry : desc.entries)
    if (const ShaderBinding* b = shader.find(entry.name))
      set.bound[static_cast<std::size_t>(b - shader.bindings.data())] = entry.resource;
  return BindingSetHandle{add(impl_->binding_sets, std::move(set))};
}

AccelHandle RecordDevice::create_blas(const BlasDesc& desc) {
  return AccelHandle{add(impl_->accels, AccelObject{desc.name, false, desc})};
}

AccelHandle RecordDevice::create_tlas(const TlasDesc& desc) {
  return AccelHandle{add(impl_->accels, AccelObject{desc.name, true, {}})};
}

TimerQueriesHandle RecordDevice::create_timer_queries(const TimerQueriesDesc& desc) {
  return TimerQueriesHandle{add(impl_->timers, TimerObject{desc})};
}

std::unique_ptr<CommandList> RecordDevice::create_command_list(std::string_view name) {
  return make_record_command_list(*impl_, name);
}

void RecordDevice::destroy(BufferHandle h) { impl_->buffer(h).destroyed = true; }
void RecordDevice::destroy(ImageHandle h) { impl_->image(h).destroyed = true; }
void RecordDevice::destroy(PipelineHandle h) { impl_->pipeline(h).destroyed = true; }
void RecordDevice::destroy(BindingSetHandle h) { impl_->binding_set(h).destroyed = true; }
void RecordDevice::destroy(AccelHandle h) { impl_->accel(h).destroyed = true; }
void RecordDevice::destroy(TimerQueriesHandle h) { impl_->timer(h).destroyed = true; }

void RecordDevice::submit(CommandList& commands) {
  for (Command& c : recorded_commands(commands)) impl_->replay(c);
}

void RecordDevice::wait() {}

void RecordDevice::upload_buffer(BufferHandle dst, std::uint64_t, std::span<const std::byte>) {
  impl_->host_access(dst, true, "upload");
}
void RecordDevice::read_buffer(BufferHandle src, std::uint64_t, std::span<std::byte> out) {
  impl_->host_access(src, false, "readback");
  std::fill(out.begin(), out.end(), std::byte{0});
}
void RecordDevice::upload_image(ImageHandle dst, std::span<const std::byte>) {
  impl_->host_access(dst, true, "upload");
}
void RecordDevice::read_image(ImageHandle src, std::span<std::byte> out) {
  impl_->host_access(src, false, "readback");
  std::fill(out.begin(), out.end(), std::byte{0});
}

std::vector<std::optional<double>> RecordDevice::read_timers(TimerQueriesHandle timers) {
  return std::vector<std::optional<double>>(impl_->timer(timers).desc.regions);  // unavailable, never zero
}

}  // namespace hal::record
