// The fault-injecting device: a forwarder that counts calls per kind and throws at the planned one.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "hal/error.hpp"
#include "hal/fault.hpp"
#include "hal/layer.hpp"

namespace hal::fault {
namespace {

class FaultDevice final : public Device, public DeviceLayer {
 public:
  FaultDevice(std::unique_ptr<Device> inner, Plan plan, bool report_counts)
      : inner_(std::move(inner)), plan_(plan), report_counts_(report_counts) {}
  ~FaultDevice() override {
    if (!report_counts_) return;
    std::string line = "fault counts:";
    for (std::size_t i = 0; i < kAllKinds.size(); ++i)
      line += std::string(i ? ", " : " ") + std::string(to_string(kAllKinds[i])) + " " + std::to_string(counts_[i]);
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  FaultDevice(const FaultDevice&) = delete;
  FaultDevice& operator=(const FaultDevice&) = delete;

  const AdapterInfo& adapter() const override { return inner_->adapter(); }
  const Capabilities& capabilities() const override { return inner_->capabilities(); }

  BufferHandle create_buffer(const BufferDesc& desc) override {
    hit(Kind::Buffer, desc.name, ErrorKind::OutOfMemory, "buffer allocation failed");
    return inner_->create_buffer(desc);
  }
  ImageHandle create_image(const ImageDesc& desc) override {
    hit(Kind::Image, desc.name, ErrorKind::OutOfMemory, "image allocation failed");
    return inner_->create_image(desc);
  }
  PipelineHandle create_pipeline(const ComputePipelineDesc& desc) override {
    hit(Kind::Pipeline, desc.name, ErrorKind::Unsupported, "the driver rejected the pipeline");
    return inner_->create_pipeline(desc);
  }
  BindingSetHandle create_binding_set(const BindingSetDesc& desc) override {
    check_lost(desc.name);
    return inner_->create_binding_set(desc);
  }
  AccelHandle create_blas(const BlasDesc& desc) override {
    check_lost(desc.name);
    return inner_->create_blas(desc);
  }
  AccelHandle create_tlas(const TlasDesc& desc) override {
    check_lost(desc.name);
    return inner_->create_tlas(desc);
  }
  TimerQueriesHandle create_timer_queries(const TimerQueriesDesc& desc) override {
    check_lost(desc.name);
    return inner_->create_timer_queries(desc);
  }
  std::unique_ptr<CommandList> create_command_list(std::string_view name) override {
    return inner_->create_command_list(name);
  }
  // Destruction always goes through: a lost device still frees what it holds.
  void destroy(BufferHandle h) override { inner_->destroy(h); }
  void destroy(ImageHandle h) override { inner_->destroy(h); }
  void destroy(PipelineHandle h) override { inner_->destroy(h); }
  void destroy(BindingSetHandle h) override { inner_->destroy(h); }
  void destroy(AccelHandle h) override { inner_->destroy(h); }
  void destroy(TimerQueriesHandle h) override { inner_->destroy(h); }
  void submit(CommandList& commands) override {
    hit(Kind::Submit, "queue", ErrorKind::DeviceLost, "the device was lost at submit");
    inner_->submit(commands);
  }
  void wait() override {
    hit(Kind::Wait, "queue", ErrorKind::DeviceLost, "the device was lost while waiting");
    inner_->wait();
  }
  void upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) override {
    hit(Kind::Upload, "buffer upload", ErrorKind::Backend, "the staging copy failed");
    inner_->upload_buffer(dst, offset, data);
  }
  void read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) override {
    hit(Kind::Readback, "buffer readback", ErrorKind::Backend, "the staging copy failed");
    inner_->read_buffer(src, offset, out);
  }
  void upload_image(ImageHandle dst, std::span<const std::byte> data) override {
    hit(Kind::Upload, "image upload", ErrorKind::Backend, "the staging copy failed");
    inner_->upload_image(dst, data);
  }
  void read_image(ImageHandle src, std::span<std::byte> out) override {
    hit(Kind::Readback, "image readback", ErrorKind::Backend, "the staging copy failed");
    inner_->read_image(src, out);
  }
  std::vector<std::optional<double>> read_timers(TimerQueriesHandle timers) override {
    check_lost("timer queries");
    return inner_->read_timers(timers);
  }
  std::optional<std::uint64_t> device_memory_bytes() const override { return inner_->device_memory_bytes(); }
  Device& inner() override { return *inner_; }

 private:
  void check_lost(std::string_view object) const {
    if (lost_) throw Error(ErrorKind::DeviceLost, object, "the device was lost earlier (injected fault)");
  }
  // Counts a call of `kind` and throws when it is the planned one.
  void hit(Kind kind, std::string_view object, ErrorKind error, std::string_view what) {
    check_lost(object);
    const std::uint32_t n = ++counts_[static_cast<std::size_t>(kind)];
    if (plan_.nth == 0 || kind != plan_.kind || n != plan_.nth) return;
    if (error == ErrorKind::DeviceLost) lost_ = true;
    throw Error(
        error, object,
        std::string(what) + " (injected fault: " + std::string(to_string(kind)) + " call " + std::to_string(n) + ")");
  }

  std::unique_ptr<Device> inner_;
  Plan plan_;
  bool report_counts_ = false;
  bool lost_ = false;
  Counts counts_{};
};

}  // namespace

std::string_view to_string(Kind kind) {
  switch (kind) {
    case Kind::Buffer:
      return "buffer";
    case Kind::Image:
      return "image";
    case Kind::Pipeline:
      return "pipeline";
    case Kind::Submit:
      return "submit";
    case Kind::Wait:
      return "wait";
    case Kind::Upload:
      return "upload";
    case Kind::Readback:
      return "readback";
  }
  return "?";
}

std::unique_ptr<Device> wrap(std::unique_ptr<Device> inner, Plan plan, bool report_counts) {
  return std::make_unique<FaultDevice>(std::move(inner), plan, report_counts);
}

std::optional<EnvironmentPlan> from_environment() {
  const char* env = std::getenv("ASVGF_FAULT");
  if (!env || !*env) return std::nullopt;
  const std::string value = env;
  if (value == "count") return EnvironmentPlan{{Kind::Buffer, 0}, true};
  const auto colon = value.find(':');
  if (colon != std::string::npos) {
    const std::string kind = value.substr(0, colon), n = value.substr(colon + 1);
    for (const Kind k : kAllKinds) {
      if (to_string(k) != kind) continue;
      char* end = nullptr;
      const unsigned long nth = std::strtoul(n.c_str(), &end, 10);
      if (!n.empty() && *end == '\0' && nth >= 1 && nth <= 1000000)
        return EnvironmentPlan{{k, static_cast<std::uint32_t>(nth)}, false};
    }
  }
  throw std::invalid_argument("ASVGF_FAULT: '" + value +
                              "' is not 'count' or <kind>:<n> with kind buffer, image, pipeline, submit, wait, "
                              "upload or readback and n >= 1");
}

}  // namespace hal::fault
