// The validating command list: checks every recorded command and the list's lifecycle, then
// forwards it to the backend's list.
#include <string>

#include "objects.hpp"

namespace hal::validate {
namespace {

bool state_allowed(ResourceKind kind, State s) {
  switch (kind) {
    case ResourceKind::Buffer:
      return s == State::Undefined || s == State::ShaderRead || s == State::ShaderWrite || s == State::CopySrc ||
             s == State::CopyDst || s == State::AccelBuildInput;
    case ResourceKind::Image:
      return s == State::Undefined || s == State::ShaderRead || s == State::ShaderWrite || s == State::CopySrc ||
             s == State::CopyDst || s == State::Present;
    case ResourceKind::Accel:
      return s == State::Undefined || s == State::AccelWrite || s == State::AccelRead || s == State::ShaderRead;
  }
  return false;
}

}  // namespace

class ValidatingCommandList final : public CommandList {
 public:
  ValidatingCommandList(Objects& objects, std::unique_ptr<CommandList> inner, std::string_view name)
      : objects_(objects), inner_(std::move(inner)), name_(name) {}

  bool belongs_to(const Objects& objects) const { return &objects == &objects_; }

  CommandList& prepare_submit() {
    if (label_depth_ != 0)
      throw Error(ErrorKind::InvalidUsage, name_, std::to_string(label_depth_) + " debug label(s) left open at submit");
    if (executing())
      throw Error(ErrorKind::InvalidUsage, name_, "submitted again while the device may still execute it; call wait()");
    submitted_ = true;
    serial_ = ++objects_.submitted;
    return *inner_;
  }

  void reset() override {
    if (executing())
      throw Error(ErrorKind::InvalidUsage, name_,
                  "reset while the device may still execute it; call Device::wait() first");
    inner_->reset();
    submitted_ = false;
    label_depth_ = 0;
  }

  void begin_label(std::string_view label) override {
    recording();
    inner_->begin_label(label);
    ++label_depth_;
  }
  void end_label() override {
    recording();
    if (label_depth_ == 0) throw Error(ErrorKind::InvalidUsage, name_, "end_label() without a matching begin_label()");
    inner_->end_label();
    --label_depth_;
  }

  void barrier(std::span<const Barrier> barriers) override {
    recording();
    for (const Barrier& b : barriers) {
      const std::string& name = objects_.resource_name(b.resource);
      for (const State s : {b.before, b.after})
        if (!state_allowed(b.resource.kind, s))
          throw Error(ErrorKind::InvalidUsage, name,
                      "barrier " + std::string(to_string(b.before)) + " -> " + std::string(to_string(b.after)) +
                          " in '" + name_ + "': " + std::string(to_string(s)) + " is not a state of " +
                          (b.resource.kind == ResourceKind::Buffer  ? "a buffer"
                           : b.resource.kind == ResourceKind::Image ? "an image"
                                                                    : "an acceleration structure"));
      if (b.after == State::Undefined)
        throw Error(ErrorKind::InvalidUsage, name,
                    "barrier to Undefined in '" + name_ + "': Undefined is only a `before` state");
    }
    inner_->barrier(barriers);
  }

  void dispatch(const DispatchDesc& desc) override {
    recording();
    const PipelineInfo& pipeline = objects_.pipelines.get(desc.pipeline.id);
    const BindingSetInfo& set = objects_.binding_sets.get(desc.bindings.id);
    const ShaderInfo& shader = *pipeline.shader;
    const std::string_view shader_name = shader.name;  // strings are built only when a rule is broken
    // Pipelines of one shader share their binding layout, so a set made for any of them fits.
    if (set.shader->name != shader.name)
      throw Error(ErrorKind::InvalidUsage, set.name(),
                  "was made for shader '" + std::string(set.shader->name) + "' but pipeline '" + pipeline.name() +
                      "' runs shader '" + std::string(shader_name) + "' (dispatch in '" + name_ + "')");
    for (std::size_t i = 0; i < shader.bindings.size(); ++i) {
      const ShaderBinding& binding = shader.bindings[i];
      if (binding.kind == BindingKind::UniformBuffer) continue;
      const Resource r = set.bound[i];
      if (r.id == 0)
        throw Error(ErrorKind::InvalidUsage, set.name(),
                    "leaves binding '" + std::string(binding.name) + "' of shader '" + std::string(shader_name) +
                        "' unbound (dispatch in '" + name_ + "')");
      if (!alive(r))
        throw Error(
            ErrorKind::InvalidHandle, set.name(),
            "binding '" + std::string(binding.name) + "' names a destroyed resource (dispatch in '" + name_ + "')");
    }
    if (desc.uniforms.size() != shader.uniform_block_size)
      throw Error(ErrorKind::InvalidUsage, pipeline.name(),
                  "dispatch passes " + std::to_string(desc.uniforms.size()) + " bytes of uniforms; shader '" +
                      std::string(shader_name) + "' has a block of " + std::to_string(shader.uniform_block_size) +
                      " (in '" + name_ + "')");
    if (desc.groups_x == 0 || desc.groups_y == 0 || desc.groups_z == 0)
      throw Error(ErrorKind::InvalidUsage, pipeline.name(),
                  "dispatch of " + std::to_string(desc.groups_x) + "x" + std::to_string(desc.groups_y) + "x" +
                      std::to_string(desc.groups_z) + " workgroups does nothing (in '" + name_ + "')");
    inner_->dispatch(desc);
  }

  void copy_buffer(const BufferCopy& copy) override {
    recording();
    const BufferInfo& src = buffer(copy.src, BufferUsage::CopySrc, "copy source");
    const BufferInfo& dst = buffer(copy.dst, BufferUsage::CopyDst, "copy destination");
    if (copy.size == 0) throw Error(ErrorKind::InvalidUsage, src.name(), "copy of 0 bytes in '" + name_ + "'");
    if (copy.src_offset > src.desc.size || copy.size > src.desc.size - copy.src_offset)
      throw Error(ErrorKind::InvalidUsage, src.name(), "copy reads past the end of the buffer in '" + name_ + "'");
    if (copy.dst_offset > dst.desc.size || copy.size > dst.desc.size - copy.dst_offset)
      throw Error(ErrorKind::InvalidUsage, dst.name(), "copy writes past the end of the buffer in '" + name_ + "'");
    inner_->copy_buffer(copy);
  }
  void copy_image(ImageHandle src_handle, ImageHandle dst_handle) override {
    recording();
    const ImageInfo& src = image(src_handle, ImageUsage::CopySrc, "copy source");
    const ImageInfo& dst = image(dst_handle, ImageUsage::CopyDst, "copy destination");
    if (src.desc.width != dst.desc.width || src.desc.height != dst.desc.height || src.desc.format != dst.desc.format)
      throw Error(ErrorKind::InvalidUsage, dst.name(),
                  "copy_image from '" + src.name() + "' needs the same size and format (in '" + name_ + "')");
    inner_->copy_image(src_handle, dst_handle);
  }
  void copy_buffer_to_image(BufferHandle src_handle, ImageHandle dst_handle) override {
    recording();
    const BufferInfo& src = buffer(src_handle, BufferUsage::CopySrc, "copy source");
    const ImageInfo& dst = image(dst_handle, ImageUsage::CopyDst, "copy destination");
    check_holds(src, dst);
    inner_->copy_buffer_to_image(src_handle, dst_handle);
  }
  void copy_image_to_buffer(ImageHandle src_handle, BufferHandle dst_handle) override {
    recording();
    const ImageInfo& src = image(src_handle, ImageUsage::CopySrc, "copy source");
    const BufferInfo& dst = buffer(dst_handle, BufferUsage::CopyDst, "copy destination");
    check_holds(dst, src);
    inner_->copy_image_to_buffer(src_handle, dst_handle);
  }
  void clear_buffer(BufferHandle handle, std::uint32_t word) override {
    recording();
    const BufferInfo& b = buffer(handle, BufferUsage::CopyDst, "clear destination");
    if (b.desc.size < 4) throw Error(ErrorKind::InvalidUsage, b.name(), "clear_buffer needs at least 4 bytes");
    inner_->clear_buffer(handle, word);
  }
  void clear_image(ImageHandle handle, std::array<float, 4> value) override {
    recording();
    image(handle, ImageUsage::CopyDst, "clear destination");
    inner_->clear_image(handle, value);
  }

  void build_blas(AccelHandle handle, bool update) override {
    recording();
    AccelInfo& a = objects_.accels.get(handle.id);
    if (a.top)
      throw Error(ErrorKind::InvalidUsage, a.name(), "build_blas on a top-level structure (in '" + name_ + "')");
    if (update && !a.blas.allow_update)
      throw Error(ErrorKind::InvalidUsage, a.name(), "update requested but the BLAS was created without allow_update");
    if (update && !a.built)
      throw Error(ErrorKind::InvalidUsage, a.name(), "update requested before any build was recorded");
    inner_->build_blas(handle, update);
    a.built = true;
  }

  void build_tlas(AccelHandle handle, std::span<const TlasInstance> list, bool update) override {
    recording();
    AccelInfo& t = objects_.accels.get(handle.id);
    if (!t.top)
      throw Error(ErrorKind::InvalidUsage, t.name(), "build_tlas on a bottom-level structure (in '" + name_ + "')");
    if (list.size() > t.tlas.max_instances)
      throw Error(
          ErrorKind::InvalidUsage, t.name(),
          std::to_string(list.size()) + " instances exceed max_instances " + std::to_string(t.tlas.max_instances));
    if (update && (!t.tlas.allow_update || !t.built))
      throw Error(ErrorKind::InvalidUsage, t.name(), "update needs allow_update and an earlier recorded build");
    if (update && list.size() != t.built_instances)
      throw Error(ErrorKind::InvalidUsage, t.name(),
                  "update with " + std::to_string(list.size()) + " instances; the last build had " +
                      std::to_string(t.built_instances) + " (an update keeps the instance count)");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const AccelInfo& blas = objects_.accels.get(list[i].blas.id);
      if (blas.top)
        throw Error(ErrorKind::InvalidUsage, t.name(),
                    "instance " + std::to_string(i) + " references top-level structure '" + blas.name() + "'");
      if (list[i].custom_index > 0xFFFFFFu)
        throw Error(ErrorKind::InvalidUsage, t.name(),
                    "instance " + std::to_string(i) + " custom_index " + std::to_string(list[i].custom_index) +
                        " does not fit in 24 bits");
    }
    inner_->build_tlas(handle, list, update);
    t.built = true;
    t.built_instances = static_cast<std::uint32_t>(list.size());
  }

  void begin_timer(TimerQueriesHandle timers, std::uint32_t region) override {
    check_region(timers, region);
    inner_->begin_timer(timers, region);
  }
  void end_timer(TimerQueriesHandle timers, std::uint32_t region) override {
    check_region(timers, region);
    inner_->end_timer(timers, region);
  }

 private:
  bool executing() const { return submitted_ && serial_ > objects_.completed; }
  void recording() const {
    if (submitted_)
      throw Error(ErrorKind::InvalidUsage, name_, "recorded into after it was submitted; call reset() first");
  }
  bool alive(Resource r) const {
    switch (r.kind) {
      case ResourceKind::Buffer:
        return objects_.buffers.alive(r.id);
      case ResourceKind::Image:
        return objects_.images.alive(r.id);
      case ResourceKind::Accel:
        return objects_.accels.alive(r.id);
    }
    return false;
  }
  const BufferInfo& buffer(BufferHandle h, BufferUsage usage, const char* role) {
    const BufferInfo& b = objects_.buffers.get(h.id);
    if (!has(b.desc.usage, usage))
      throw Error(ErrorKind::InvalidUsage, b.name(),
                  std::string("used as ") + role + " in command list '" + name_ + "' but created without that usage");
    return b;
  }
  const ImageInfo& image(ImageHandle h, ImageUsage usage, const char* role) {
    const ImageInfo& i = objects_.images.get(h.id);
    if (!has(i.desc.usage, usage))
      throw Error(ErrorKind::InvalidUsage, i.name(),
                  std::string("used as ") + role + " in command list '" + name_ + "' but created without that usage");
    return i;
  }
  void check_holds(const BufferInfo& b, const ImageInfo& i) const {
    if (b.desc.size < i.bytes())
      throw Error(ErrorKind::InvalidUsage, b.name(),
                  "holds " + std::to_string(b.desc.size) + " bytes; image '" + i.name() + "' needs " +
                      std::to_string(i.bytes()) + " (in '" + name_ + "')");
  }
  void check_region(TimerQueriesHandle timers, std::uint32_t region) {
    recording();
    const TimerInfo& t = objects_.timers.get(timers.id);
    if (region >= t.desc.regions)
      throw Error(
          ErrorKind::InvalidUsage, t.name(),
          "region " + std::to_string(region) + " out of " + std::to_string(t.desc.regions) + " (in '" + name_ + "')");
  }

  Objects& objects_;
  std::unique_ptr<CommandList> inner_;
  std::string name_;
  int label_depth_ = 0;
  bool submitted_ = false;
  std::uint64_t serial_ = 0;
};

std::unique_ptr<CommandList> make_command_list(Objects& objects, std::unique_ptr<CommandList> inner,
                                               std::string_view name) {
  return std::make_unique<ValidatingCommandList>(objects, std::move(inner), name);
}

CommandList& prepare_submit(Objects& objects, CommandList& list) {
  auto* ours = dynamic_cast<ValidatingCommandList*>(&list);
  if (!ours || !ours->belongs_to(objects))
    throw Error(ErrorKind::InvalidUsage, "command list", "was not created by this validating device");
  return ours->prepare_submit();
}

}  // namespace hal::validate
