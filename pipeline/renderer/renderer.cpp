// Rendering frame after frame: scene update, graph build and compile, execute, readback.
#include "renderer/renderer.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>

#include "hal/error.hpp"
#include "io/half_float.hpp"

namespace asvgf::render {
namespace {

// Reference frames are traced in equal batches so that no single dispatch runs for long (GPU
// watchdogs) and each batch weighs the same in the running mean.
constexpr std::uint32_t kMaxBatchSpp = 64;

bool pick_ray_query(const hal::Device& device, const RenderSettings& s) {
  return s.ray_query.value_or(device.capabilities().ray_query);
}

// The denoiser's settings pass the same check as asvgf::Denoiser's (asvgf/denoise_settings.hpp).
void check_denoise_settings(const RenderSettings& s) {
  if (const auto problem = check_settings(s.denoise))
    throw hal::Error(hal::ErrorKind::InvalidDescriptor, std::string("denoiser setting ") + problem->setting.setting,
                     problem->message());
}

}  // namespace

Renderer::Renderer(hal::Device& device, const scene::Scene& scene, const RenderSettings& settings)
    : device_(device),
      settings_(settings),
      scene_gpu_(device, scene, pick_ray_query(device, settings)),
      runtime_(device),
      builder_(device),
      commands_(device.create_command_list("frame")) {
  const auto max = device.capabilities().max_image_dimension;
  if (settings.width == 0 || settings.height == 0 || settings.width > max || settings.height > max)
    throw hal::Error(hal::ErrorKind::InvalidDescriptor, "render size",
                     std::to_string(settings.width) + "x" + std::to_string(settings.height) + " is outside 1.." +
                         std::to_string(max));
  if (settings.spp == 0) throw hal::Error(hal::ErrorKind::InvalidDescriptor, "spp", "samples per pixel must be >= 1");
  check_denoise_settings(settings);
  set_batches();
  const auto usage = hal::ImageUsage::Storage | hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc;
  create_hdr_target();
  targets_.display = device.create_image({"display", settings.width, settings.height, hal::Format::RGBA8Unorm, usage});
  targets_.ray_counter = device.create_buffer(
      {"ray_counter", 16, hal::BufferUsage::Storage | hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst});
  if (settings.debug_view)
    targets_.debug =
        device.create_image({"debug_view", settings.width, settings.height, hal::Format::RGBA8Unorm, usage});
  if (settings.aovs) create_aov_targets();
}

// The radiance image in the format settings_.method writes (frame::hdr_format).
void Renderer::create_hdr_target() {
  targets_.hdr_format = frame::hdr_format(settings_.method);
  targets_.hdr = device_.create_image({"hdr", settings_.width, settings_.height, targets_.hdr_format,
                                       hal::ImageUsage::Storage | hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc});
  targets_.hdr_state = hal::State::Undefined;
}

void Renderer::create_aov_targets() {
  if (settings_.method == frame::Method::Reference)
    throw hal::Error(hal::ErrorKind::InvalidUsage, "renderer AOVs",
                     "the reference method has no denoiser inputs to export");
  const auto usage =
      hal::ImageUsage::Storage | hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst;
  const std::uint32_t w = settings_.width, h = settings_.height;
  auto image = [&](const char* name, std::uint32_t iw, std::uint32_t ih) {
    return frame::ImageTarget{device_.create_image({name, iw, ih, hal::Format::RGBA32F, usage})};
  };
  targets_.aovs =
      frame::AovTargets{image("aov.illumination", w, h), image("aov.albedo", w, h),
                        image("aov.normal", w, h),       image("aov.depth", w, h),
                        image("aov.motion", w, h),       image("aov.gradient_samples", (w + 2) / 3, (h + 2) / 3)};
}

void Renderer::destroy_aov_targets() {
  if (!targets_.aovs) return;
  auto& a = *targets_.aovs;
  for (auto* t : {&a.illumination, &a.albedo, &a.normal, &a.depth, &a.motion, &a.gradient_samples})
    device_.destroy(t->image);
  targets_.aovs.reset();
}

AovImages Renderer::read_aovs(bool gradient_ran) {
  auto& a = *targets_.aovs;
  AovImages out;
  const std::size_t n = std::size_t(settings_.width) * settings_.height * 4;
  auto read = [&](frame::ImageTarget& t, std::vector<float>& to, std::size_t count) {
    to.resize(count);
    device_.read_image(t.image, std::as_writable_bytes(std::span(to)));
  };
  read(a.illumination, out.illumination, n);
  read(a.albedo, out.albedo, n);
  read(a.normal, out.normal, n);
  read(a.depth, out.depth, n);
  read(a.motion, out.motion, n);
  const std::size_t strata = std::size_t((settings_.width + 2) / 3) * ((settings_.height + 2) / 3) * 4;
  out.gradient_ran = gradient_ran;
  if (settings_.method != frame::Method::Asvgf) return out;
  if (gradient_ran) {
    read(a.gradient_samples, out.gradient_samples, strata);
  } else {
    out.gradient_samples.assign(strata, 0.0f);
    for (std::size_t i = 1; i < strata; i += 4) out.gradient_samples[i] = -1.0f;
  }
  return out;
}

void Renderer::set_batches() {
  batches_ = 1;
  batch_spp_ = settings_.spp;
  if (settings_.method == frame::Method::Reference) {
    batches_ = (settings_.spp + kMaxBatchSpp - 1) / kMaxBatchSpp;
    batch_spp_ = (settings_.spp + batches_ - 1) / batches_;
  }
}

void Renderer::set_settings(const RenderSettings& s) {
  if (s.width != settings_.width || s.height != settings_.height || s.seed != settings_.seed ||
      s.ray_query != settings_.ray_query)
    throw hal::Error(hal::ErrorKind::InvalidUsage, "renderer", "size, seed and tracing variant are fixed at creation");
  if (s.spp == 0) throw hal::Error(hal::ErrorKind::InvalidDescriptor, "spp", "samples per pixel must be >= 1");
  check_denoise_settings(s);
  // Another method's histories hold another quantity, or nothing recent: start afresh.
  if (s.method != settings_.method) runtime_.reset_histories();
  // raw and reference write unclamped RGBA32F radiance, the filtered methods RGBA16F.
  const bool new_hdr_format = frame::hdr_format(s.method) != targets_.hdr_format;
  if (new_hdr_format) {
    device_.wait();
    device_.destroy(targets_.hdr);
  }
  if (s.debug_view && !targets_.debug) {
    const auto usage = hal::ImageUsage::Storage | hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc;
    targets_.debug = device_.create_image({"debug_view", s.width, s.height, hal::Format::RGBA8Unorm, usage});
    targets_.debug_state = hal::State::Undefined;
  }
  settings_ = s;
  if (new_hdr_format) create_hdr_target();
  set_batches();
  if (s.aovs && !targets_.aovs) create_aov_targets();
  if (!s.aovs) destroy_aov_targets();
}

Renderer::~Renderer() {
  try {
    device_.wait();
    commands_.reset();
    device_.destroy(targets_.hdr);
    device_.destroy(targets_.display);
    device_.destroy(targets_.ray_counter);
    if (targets_.debug) device_.destroy(targets_.debug);
    destroy_aov_targets();
  } catch (...) {
    // Nothing to release on a lost device.
  }
}

FrameImages Renderer::render(int frame) {
  if (frame <= last_frame_) runtime_.reset_histories();  // a jump back: nothing from before is valid
  const bool moved = scene_gpu_.update(static_cast<float>(frame) * settings_.time_per_frame);
  const bool first = last_frame_ < 0 || frame <= last_frame_;
  moved_last_frame_ = moved && !first;
  last_frame_ = frame;
  // A progressive reference continues last frame's mean while nothing moved (after a method change
  // the runtime's reset histories make the accumulation read as unwritten zeros: a fresh start).
  const bool continue_mean = settings_.progressive && !moved && !first;

  std::map<std::string, double> totals;
  std::vector<std::string> order;
  bool have_times = true;
  const std::uint32_t batches = settings_.method == frame::Method::Reference ? batches_ : 1;
  const std::array<std::uint32_t, 4> zero{};
  device_.upload_buffer(targets_.ray_counter, 0, std::as_bytes(std::span(zero)));
  targets_.ray_counter_state = hal::State::CopyDst;
  bool gradient_ran = false;
  for (std::uint32_t b = 0; b < batches; ++b) {
    frame::FrameSettings s;
    static_cast<frame::FrameConfig&>(s) = settings_;
    s.spp = batch_spp_;
    s.scene_moved = moved && !first;
    s.frame = static_cast<std::uint32_t>(frame) * 4096u + b;
    s.accumulation_valid = b > 0 || continue_mean;
    gradient_ran = frame::reshades_gradients(s);
    last_graph_.emplace(builder_.build(s, scene_gpu_, targets_));
    last_compiled_.emplace(runtime_.compile(*last_graph_));
    commands_->reset();
    runtime_.execute(*last_compiled_, *commands_);
    device_.submit(*commands_);
    device_.wait();
    targets_.hdr_state = targets_.display_state = targets_.ray_counter_state = hal::State::CopySrc;
    if (settings_.debug_view) targets_.debug_state = hal::State::CopySrc;
    if (targets_.aovs) {
      auto& a = *targets_.aovs;
      for (auto* t : {&a.illumination, &a.albedo, &a.normal, &a.depth, &a.motion}) t->state = hal::State::CopySrc;
      if (gradient_ran) a.gradient_samples.state = hal::State::CopySrc;
    }
    for (const auto& t : runtime_.timings()) {
      if (!totals.count(t.pass)) order.push_back(t.pass);
      totals[t.pass] += t.gpu_ms.value_or(0.0);
      have_times = have_times && t.gpu_ms.has_value();
    }
  }
  timings_.clear();
  for (const auto& name : order)
    timings_.push_back({name, have_times ? std::optional<double>(totals[name]) : std::nullopt});

  std::uint32_t rays = 0;
  device_.read_buffer(targets_.ray_counter, 0, std::as_writable_bytes(std::span(&rays, 1)));
  rays_last_frame_ = rays + std::uint64_t(settings_.width) * settings_.height * batches;

  FrameImages out;
  out.width = settings_.width;
  out.height = settings_.height;
  if (!settings_.read_back) return out;
  out.hdr.resize(std::size_t(out.width) * out.height * 4);
  out.display.resize(std::size_t(out.width) * out.height * 4);
  if (targets_.hdr_format == hal::Format::RGBA16F) {
    std::vector<std::uint16_t> halves(out.hdr.size());
    device_.read_image(targets_.hdr, std::as_writable_bytes(std::span(halves)));
    std::transform(halves.begin(), halves.end(), out.hdr.begin(), io::half_to_float);
  } else {
    device_.read_image(targets_.hdr, std::as_writable_bytes(std::span(out.hdr)));
  }
  device_.read_image(targets_.display, std::as_writable_bytes(std::span(out.display)));
  if (settings_.debug_view) {
    out.debug.resize(out.display.size());
    device_.read_image(targets_.debug, std::as_writable_bytes(std::span(out.debug)));
  }
  if (targets_.aovs) out.aovs = read_aovs(gradient_ran);
  return out;
}

}  // namespace asvgf::render
