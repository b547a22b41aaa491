// The recording device's command list: validates handles and stores commands for submit().
#include <string>

#include "impl.hpp"

namespace hal::record {
namespace {

class RecordCommandList final : public CommandList {
 public:
  RecordCommandList(RecordDevice::Impl& device, std::string_view name) : device_(device), name_(name) {}

  std::vector<Command>& commands() { return commands_; }

  void reset() override {
    commands_.clear();
    labels_.clear();
  }

  void begin_label(std::string_view label) override { labels_.emplace_back(label); }
  void end_label() override {
    if (!labels_.empty()) labels_.pop_back();
  }

  void barrier(std::span<const Barrier> barriers) override {
    std::string names;
    for (const auto& b : barriers) {
      device_.check_exists(b.resource);
      names += (names.empty() ? "" : ", ") + device_.name_of(b.resource) + " " + std::string(to_string(b.before)) +
               "->" + std::string(to_string(b.after));
    }
    Command c = make(Command::Op::Barrier, "barrier " + names);
    c.barriers.assign(barriers.begin(), barriers.end());
    commands_.push_back(std::move(c));
  }

  void dispatch(const DispatchDesc& desc) override {
    auto& pipeline = device_.pipeline(desc.pipeline);
    device_.binding_set(desc.bindings);
    Command c = make(Command::Op::Dispatch, "dispatch " + pipeline.name);
    c.dispatch = desc;
    c.dispatch.uniforms = {};
    commands_.push_back(std::move(c));
  }

  void copy_buffer(const BufferCopy& copy) override {
    auto& src = device_.buffer(copy.src);
    auto& dst = device_.buffer(copy.dst);
    copy_command("copy " + src.desc.name + " -> " + dst.desc.name, copy.src, copy.dst);
  }
  void copy_image(ImageHandle src, ImageHandle dst) override {
    auto& s = device_.image(src);
    auto& d = device_.image(dst);
    copy_command("copy " + s.desc.name + " -> " + d.desc.name, src, dst);
  }
  void copy_buffer_to_image(BufferHandle src, ImageHandle dst) override {
    copy_command("copy " + device_.buffer(src).desc.name + " -> " + device_.image(dst).desc.name, src, dst);
  }
  void copy_image_to_buffer(ImageHandle src, BufferHandle dst) override {
    copy_command("copy " + device_.image(src).desc.name + " -> " + device_.buffer(dst).desc.name, src, dst);
  }
  void clear_buffer(BufferHandle buffer, std::uint32_t) override {
    clear_command(buffer, device_.buffer(buffer).desc.name);
  }
  void clear_image(ImageHandle image, std::array<float, 4>) override {
    clear_command(image, device_.image(image).desc.name);
  }

  void build_blas(AccelHandle blas, bool update) override {
    auto& a = device_.accel(blas);
    Command c = make(Command::Op::BuildBlas, std::string(update ? "update" : "build") + " blas " + a.name);
    if (a.blas.geometry == BlasGeometry::Boxes) {
      c.uses.push_back({a.blas.boxes, true, false, State::AccelBuildInput, "box buffer"});
    } else {
      c.uses.push_back({a.blas.vertices, true, false, State::AccelBuildInput, "vertex buffer"});
      c.uses.push_back({a.blas.indices, true, false, State::AccelBuildInput, "index buffer"});
    }
    c.uses.push_back({blas, update, true, State::AccelWrite, "built structure"});
    commands_.push_back(std::move(c));
  }

  void build_tlas(AccelHandle tlas, std::span<const TlasInstance> instances, bool update) override {
    auto& t = device_.accel(tlas);
    Command c = make(Command::Op::BuildTlas, std::string(update ? "update" : "build") + " tlas " + t.name);
    for (const auto& instance : instances) {
      c.uses.push_back({instance.blas, true, false, State::AccelRead, "instance"});
    }
    c.uses.push_back({tlas, update, true, State::AccelWrite, "built structure"});
    commands_.push_back(std::move(c));
  }

  void begin_timer(TimerQueriesHandle timers, std::uint32_t region) override { timer(timers, region, "begin"); }
  void end_timer(TimerQueriesHandle timers, std::uint32_t region) override { timer(timers, region, "end"); }

 private:
  Command make(Command::Op op, const std::string& what) {
    Command c;
    c.op = op;
    std::string path;
    for (const auto& l : labels_) path += (path.empty() ? "" : "/") + l;
    c.name = path.empty() ? what : path + ": " + what;
    return c;
  }
  void copy_command(const std::string& what, Resource src, Resource dst) {
    Command c = make(Command::Op::Copy, what);
    c.uses.push_back({src, true, false, State::CopySrc, "copy source"});
    c.uses.push_back({dst, false, true, State::CopyDst, "copy destination"});
    commands_.push_back(std::move(c));
  }
  void clear_command(Resource r, const std::string& name) {
    Command c = make(Command::Op::Clear, "clear " + name);
    c.uses.push_back({r, false, true, State::CopyDst, "clear destination"});
    commands_.push_back(std::move(c));
  }
  void timer(TimerQueriesHandle timers, std::uint32_t region, const char* which) {
    auto& t = device_.timer(timers);
    commands_.push_back(make(Command::Op::Timer, std::string(which) + " timer " + t.desc.name + "[" +
                                                     std::to_string(region) + "]"));
  }

  RecordDevice::Impl& device_;
  std::string name_;
  std::vector<Command> commands_;
  std::vector<std::string> labels_;
};

}  // namespace

std::unique_ptr<CommandList> make_record_command_list(RecordDevice::Impl& device, std::string_view name) {
  return std::make_unique<RecordCommandList>(device, name);
}

std::vector<Command>& recorded_commands(CommandList& list) {
  auto* record = dynamic_cast<RecordCommandList*>(&list);
  if (!record)
    throw Error(ErrorKind::InvalidUsage, "command list", "was not created by this recording device");
  return record->commands();
}

}  // namespace hal::record
