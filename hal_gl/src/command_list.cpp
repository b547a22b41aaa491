// Command lists: recorded on the host as closures over the device, replayed into the context at
// submit (GL has no command buffers). Uniform bytes are copied at record time.
#include <functional>
#include <vector>

#include "device.hpp"

namespace hal::gl {
namespace {

class GlCommandList final : public CommandList {
 public:
  GlCommandList(GlDevice& device, std::string_view name) : device_(device), name_(name) {}

  void replay() {
    device_.make_current();
    for (const auto& command : commands_) command(device_);
    device_.check_gl(name_, "submit");
  }

  void reset() override { commands_.clear(); }

  void begin_label(std::string_view label) override {
    if (!device_.debug_groups()) return;
    commands_.push_back([text = std::string(label)](GlDevice&) {
      glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(text.size()), text.data());
    });
  }
  void end_label() override {
    if (!device_.debug_groups()) return;
    commands_.push_back([](GlDevice&) { glPopDebugGroup(); });
  }

  void barrier(std::span<const Barrier> barriers) override {
    for (const Barrier& b : barriers) commands_.push_back([b](GlDevice& d) { d.memory_barrier(b.before, b.after); });
  }

  void dispatch(const DispatchDesc& desc) override {
    std::vector<std::byte> uniforms(desc.uniforms.begin(), desc.uniforms.end());
    commands_.push_back([desc, uniforms = std::move(uniforms)](GlDevice& d) {
      d.dispatch(desc.pipeline, desc.bindings, uniforms, desc.groups_x, desc.groups_y, desc.groups_z);
    });
  }

  void copy_buffer(const BufferCopy& copy) override {
    commands_.push_back([copy](GlDevice& d) { d.copy_buffer(copy); });
  }
  void copy_image(ImageHandle src, ImageHandle dst) override {
    commands_.push_back([src, dst](GlDevice& d) { d.copy_image(src, dst); });
  }
  void copy_buffer_to_image(BufferHandle src, ImageHandle dst) override {
    commands_.push_back([src, dst](GlDevice& d) { d.copy_buffer_to_image(src, dst); });
  }
  void copy_image_to_buffer(ImageHandle src, BufferHandle dst) override {
    commands_.push_back([src, dst](GlDevice& d) { d.copy_image_to_buffer(src, dst); });
  }
  void clear_buffer(BufferHandle buffer, std::uint32_t word) override {
    commands_.push_back([buffer, word](GlDevice& d) { d.clear_buffer(buffer, word); });
  }
  void clear_image(ImageHandle image, std::array<float, 4> value) override {
    commands_.push_back([image, value](GlDevice& d) { d.clear_image(image, value); });
  }

  void build_blas(AccelHandle, bool) override {
    throw Error(ErrorKind::Unsupported, name_, "OpenGL has no acceleration structures");
  }
  void build_tlas(AccelHandle, std::span<const TlasInstance>, bool) override {
    throw Error(ErrorKind::Unsupported, name_, "OpenGL has no acceleration structures");
  }

  void begin_timer(TimerQueriesHandle timers, std::uint32_t region) override {
    commands_.push_back([timers, region](GlDevice& d) { d.timestamp(timers, 2 * region); });
  }
  void end_timer(TimerQueriesHandle timers, std::uint32_t region) override {
    commands_.push_back([timers, region](GlDevice& d) { d.timestamp(timers, 2 * region + 1); });
  }

  GlDevice& device() { return device_; }

 private:
  GlDevice& device_;
  std::string name_;
  std::vector<std::function<void(GlDevice&)>> commands_;
};

}  // namespace

std::unique_ptr<CommandList> GlDevice::create_command_list(std::string_view name) {
  return std::make_unique<GlCommandList>(*this, name);
}

void GlDevice::submit(CommandList& commands) {
  auto* list = dynamic_cast<GlCommandList*>(&commands);
  if (!list || &list->device() != this)
    throw Error(ErrorKind::InvalidUsage, "command list", "was not created by this OpenGL device");
  list->replay();
}

}  // namespace hal::gl
