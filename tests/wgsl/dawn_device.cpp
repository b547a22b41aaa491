#include "dawn_device.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>
#include <unordered_map>
#include <vector>

#include "hal/error.hpp"

extern char** environ;

namespace hal::dawn_node {
namespace {

using nlohmann::json;

std::string base64(std::span<const std::byte> data) {
  static const char* const digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < data.size(); i += 3) {
    std::uint32_t v = std::to_integer<std::uint32_t>(data[i]) << 16;
    if (i + 1 < data.size()) v |= std::to_integer<std::uint32_t>(data[i + 1]) << 8;
    if (i + 2 < data.size()) v |= std::to_integer<std::uint32_t>(data[i + 2]);
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < data.size() ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < data.size() ? digits[v & 63] : '=';
  }
  return out;
}

// The server process and the two pipes to it.
class Server {
 public:
  explicit Server(const DeviceOptions& o) {
    int to_child[2], from_child[2];
    if (pipe(to_child) != 0 || pipe(from_child) != 0)
      throw Error(ErrorKind::NoDevice, "WebGPU (Dawn)", "cannot create pipes");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, to_child[0], 0);
    posix_spawn_file_actions_adddup2(&actions, from_child[1], 1);
    posix_spawn_file_actions_addclose(&actions, to_child[1]);
    posix_spawn_file_actions_addclose(&actions, from_child[0]);
    std::vector<std::string> args = {o.node, o.server, o.node_modules, o.shader_dir};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int spawned = posix_spawnp(&pid_, o.node.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(to_child[0]);
    close(from_child[1]);
    to_ = to_child[1];
    from_ = from_child[0];
    if (spawned != 0) {
      close(to_);
      close(from_);
      throw Error(ErrorKind::NoDevice, "WebGPU (Dawn)", "cannot start " + o.node + ": " + std::strerror(spawned));
    }
    signal(SIGPIPE, SIG_IGN);  // a dead server shows as a failed write, not a killed test
  }
  ~Server() {
    close(to_);  // end of input: the server finishes and exits
    int status = 0;
    waitpid(pid_, &status, 0);
    close(from_);
  }
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Sends one request and returns the reply's JSON; its payload (if any) goes to `payload_out`.
  json call(const json& request, std::span<const std::byte> payload = {},
            std::vector<std::byte>* payload_out = nullptr) {
    json r = request;
    if (!payload.empty()) r["bytes"] = payload.size();
    const std::string line = r.dump() + "\n";
    write_all(line.data(), line.size());
    if (!payload.empty()) write_all(payload.data(), payload.size());
    std::string header;
    for (char c; read_all(&c, 1), c != '\n';) header += c;
    json reply = json::parse(header);
    if (reply.contains("bytes")) {
      std::vector<std::byte> bytes(reply["bytes"].get<std::size_t>());
      read_all(bytes.data(), bytes.size());
      if (payload_out) *payload_out = std::move(bytes);
    }
    return reply;
  }

 private:
  void write_all(const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
      const ssize_t n = write(to_, p, size);
      if (n <= 0) throw Error(ErrorKind::DeviceLost, "WebGPU (Dawn)", "the Node server stopped reading");
      p += n;
      size -= static_cast<std::size_t>(n);
    }
  }
  void read_all(void* data, std::size_t size) {
    char* p = static_cast<char*>(data);
    while (size > 0) {
      const ssize_t n = read(from_, p, size);
      if (n <= 0) throw Error(ErrorKind::DeviceLost, "WebGPU (Dawn)", "the Node server exited (its stderr says why)");
      p += n;
      size -= static_cast<std::size_t>(n);
    }
  }
  pid_t pid_ = 0;
  int to_ = -1, from_ = -1;
};

class DawnDevice;

class DawnCommandList final : public CommandList {
 public:
  DawnCommandList(DawnDevice& device, std::string name) : device_(device), name_(std::move(name)) {}
  void reset() override { ops_ = json::array(); }
  void begin_label(std::string_view label) override { labels_.emplace_back(label); }
  void end_label() override {
    if (!labels_.empty()) labels_.pop_back();
  }
  void barrier(std::span<const Barrier>) override {}
  void dispatch(const DispatchDesc& desc) override;
  void copy_buffer(const BufferCopy& c) override {
    ops_.push_back({{"op", "copy_buffer"},
                    {"src", c.src.id},
                    {"dst", c.dst.id},
                    {"src_offset", c.src_offset},
                    {"dst_offset", c.dst_offset},
                    {"size", c.size}});
  }
  void copy_image(ImageHandle src, ImageHandle dst) override {
    ops_.push_back({{"op", "copy_image"}, {"src", src.id}, {"dst", dst.id}});
  }
  void copy_buffer_to_image(BufferHandle src, ImageHandle dst) override {
    ops_.push_back({{"op", "copy_buffer_to_image"}, {"src", src.id}, {"dst", dst.id}});
  }
  void copy_image_to_buffer(ImageHandle src, BufferHandle dst) override {
    ops_.push_back({{"op", "copy_image_to_buffer"}, {"src", src.id}, {"dst", dst.id}});
  }
  void clear_buffer(BufferHandle buffer, std::uint32_t word) override {
    ops_.push_back({{"op", "clear_buffer"}, {"id", buffer.id}, {"word", word}});
  }
  void clear_image(ImageHandle image, std::array<float, 4> value) override {
    ops_.push_back({{"op", "clear_image"}, {"id", image.id}, {"value", value}});
  }
  void build_blas(AccelHandle, bool) override { unsupported(); }
  void build_tlas(AccelHandle, std::span<const TlasInstance>, bool) override { unsupported(); }
  void begin_timer(TimerQueriesHandle, std::uint32_t) override {}  // no timestamps: times stay empty
  void end_timer(TimerQueriesHandle, std::uint32_t) override {}

  const json& ops() const { return ops_; }
  const std::string& name() const { return name_; }

 private:
  [[noreturn]] void unsupported() const {
    throw Error(ErrorKind::Unsupported, name_, "the WebGPU test backend has no acceleration structures");
  }
  DawnDevice& device_;
  std::string name_;
  std::vector<std::string> labels_;
  json ops_ = json::array();
};

class DawnDevice final : public Device {
 public:
  explicit DawnDevice(const DeviceOptions& options) : options_(options), server_(options) {
    const json hello = call({{"op", "hello"}}, "WebGPU (Dawn)");
    adapter_.name = hello["adapter"].get<std::string>();
    adapter_.driver = "Dawn (npm webgpu) through Node";
    adapter_.api_version = "WebGPU";
    adapter_.type =
        adapter_.name.find("llvmpipe") != std::string::npos || adapter_.name.find("lavapipe") != std::string::npos
            ? DeviceType::Cpu
            : DeviceType::Other;
    capabilities_.max_image_dimension = hello["limits"]["maxTextureDimension2D"].get<std::uint32_t>();
    capabilities_.max_storage_buffer_range = hello["limits"]["maxStorageBufferBindingSize"].get<std::uint64_t>();
    capabilities_.max_buffer_size = hello["limits"]["maxBufferSize"].get<std::uint64_t>();
  }

  const AdapterInfo& adapter() const override { return adapter_; }
  const Capabilities& capabilities() const override { return capabilities_; }

  BufferHandle create_buffer(const BufferDesc& desc) override {
    const std::uint32_t id = next_++;
    call({{"op", "create_buffer"}, {"id", id}, {"size", desc.size}, {"name", desc.name}}, desc.name);
    buffers_[id] = desc;
    return BufferHandle{id};
  }
  ImageHandle create_image(const ImageDesc& desc) override {
    const std::uint32_t id = next_++;
    call({{"op", "create_image"},
          {"id", id},
          {"width", desc.width},
          {"height", desc.height},
          {"format", std::string(format_name(desc.format))},
          {"storage", has(desc.usage, ImageUsage::Storage)},
          {"name", desc.name}},
         desc.name);
    images_[id] = desc;
    return ImageHandle{id};
  }
  PipelineHandle create_pipeline(const ComputePipelineDesc& desc) override {
    if (desc.shader->uses_ray_query) throw Error(ErrorKind::Unsupported, desc.name, "ray-query variants have no WGSL");
    const std::uint32_t id = next_++;
    call({{"op", "create_pipeline"}, {"id", id}, {"shader", std::string(desc.shader->name)}, {"name", desc.name}},
         desc.name);
    pipelines_[id] = desc.shader;
    return PipelineHandle{id};
  }
  BindingSetHandle create_binding_set(const BindingSetDesc& desc) override {
    const ShaderInfo* shader = pipelines_.at(desc.pipeline.id);
    json entries = json::array();
    for (const auto& e : desc.entries) {
      const ShaderBinding* b = shader->find(e.name);
      if (!b) throw Error(ErrorKind::InvalidUsage, desc.name, "no binding '" + e.name + "'");
      entries.push_back({{"group", b->set},
                         {"binding", b->binding},
                         {"resource", e.resource.kind == ResourceKind::Buffer ? "buffer" : "image"},
                         {"id", e.resource.id}});
    }
    const std::uint32_t id = next_++;
    call({{"op", "create_binding_set"}, {"id", id}, {"pipeline", desc.pipeline.id}, {"entries", entries}}, desc.name);
    sets_[id] = shader;
    return BindingSetHandle{id};
  }
  AccelHandle create_blas(const BlasDesc& desc) override { throw no_accel(desc.name); }
  AccelHandle create_tlas(const TlasDesc& desc) override { throw no_accel(desc.name); }
  TimerQueriesHandle create_timer_queries(const TimerQueriesDesc& desc) override {
    const std::uint32_t id = next_++;
    timers_[id] = desc.regions;
    return TimerQueriesHandle{id};
  }
  std::unique_ptr<CommandList> create_command_list(std::string_view name) override {
    return std::make_unique<DawnCommandList>(*this, std::string(name));
  }
  void destroy(BufferHandle h) override { forget("buffer", h.id), buffers_.erase(h.id); }
  void destroy(ImageHandle h) override { forget("image", h.id), images_.erase(h.id); }
  void destroy(PipelineHandle h) override { forget("pipeline", h.id), pipelines_.erase(h.id); }
  void destroy(BindingSetHandle h) override { forget("binding_set", h.id), sets_.erase(h.id); }
  void destroy(AccelHandle) override {}
  void destroy(TimerQueriesHandle h) override { timers_.erase(h.id); }
  void submit(CommandList& commands) override {
    auto& list = static_cast<DawnCommandList&>(commands);
    call({{"op", "submit"}, {"ops", list.ops()}}, list.name());
  }
  void wait() override { call({{"op", "wait"}}, "wait"); }
  void upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) override {
    call({{"op", "upload_buffer"}, {"id", dst.id}, {"offset", offset}}, buffers_.at(dst.id).name, data);
  }
  void read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) override {
    std::vector<std::byte> bytes;
    call({{"op", "read_buffer"}, {"id", src.id}, {"offset", offset}, {"size", out.size()}}, buffers_.at(src.id).name,
         {}, &bytes);
    std::memcpy(out.data(), bytes.data(), std::min(out.size(), bytes.size()));
  }
  void upload_image(ImageHandle dst, std::span<const std::byte> data) override {
    call({{"op", "upload_image"}, {"id", dst.id}}, images_.at(dst.id).name, data);
  }
  void read_image(ImageHandle src, std::span<std::byte> out) override {
    std::vector<std::byte> bytes;
    call({{"op", "read_image"}, {"id", src.id}}, images_.at(src.id).name, {}, &bytes);
    std::memcpy(out.data(), bytes.data(), std::min(out.size(), bytes.size()));
  }
  std::vector<std::optional<double>> read_timers(TimerQueriesHandle timers) override {
    return std::vector<std::optional<double>>(timers_.at(timers.id));
  }

  const ShaderInfo& set_shader(BindingSetHandle set) const { return *sets_.at(set.id); }

 private:
  json call(const json& request, const std::string& object, std::span<const std::byte> payload = {},
            std::vector<std::byte>* out = nullptr) {
    const json reply = server_.call(request, payload, out);
    if (reply.contains("errors"))
      for (const auto& e : reply["errors"]) report(object + ": " + e.get<std::string>());
    if (!reply["ok"].get<bool>()) throw Error(ErrorKind::Backend, object, reply["error"].get<std::string>());
    return reply;
  }
  void report(const std::string& message) {
    if (options_.on_message)
      options_.on_message(message);
    else
      std::fprintf(stderr, "Dawn: %s\n", message.c_str());
  }
  void forget(const char* kind, std::uint32_t id) { call({{"op", "destroy"}, {"kind", kind}, {"id", id}}, kind); }
  static Error no_accel(const std::string& name) {
    return Error(ErrorKind::Unsupported, name, "the WebGPU test backend has no acceleration structures");
  }

  DeviceOptions options_;
  Server server_;
  AdapterInfo adapter_;
  Capabilities capabilities_;
  std::uint32_t next_ = 1;
  std::unordered_map<std::uint32_t, BufferDesc> buffers_;
  std::unordered_map<std::uint32_t, ImageDesc> images_;
  std::unordered_map<std::uint32_t, const ShaderInfo*> pipelines_;
  std::unordered_map<std::uint32_t, const ShaderInfo*> sets_;
  std::unordered_map<std::uint32_t, std::uint32_t> timers_;
};

void DawnCommandList::dispatch(const DispatchDesc& desc) {
  const ShaderInfo& shader = device_.set_shader(desc.bindings);
  json op = {{"op", "dispatch"},   {"set", desc.bindings.id},
             {"x", desc.groups_x}, {"y", desc.groups_y},
             {"z", desc.groups_z}, {"label", labels_.empty() ? std::string(shader.name) : labels_.back()}};
  for (const auto& b : shader.bindings)
    if (b.kind == BindingKind::UniformBuffer && !desc.uniforms.empty()) {
      op["uniforms"] = base64(desc.uniforms);
      op["uniform_group"] = b.set;
      op["uniform_binding"] = b.binding;
    }
  ops_.push_back(std::move(op));
}

}  // namespace

std::unique_ptr<hal::Device> create_device(const DeviceOptions& options) {
  return std::make_unique<DawnDevice>(options);
}

}  // namespace hal::dawn_node
