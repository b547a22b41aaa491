// asvgf::Denoiser (include/asvgf/denoiser.hpp): the caller's images imported into a render graph of
// pack_surface + add_denoiser (the same chain the frame runs), compiled and recorded every frame.
#include "asvgf/denoiser.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <span>
#include <string>

#include "asvgf/denoiser_graph.hpp"
#include "asvgf/graph_runtime.hpp"
#include "denoiser/api/input_report.hpp"
#include "denoiser/passes/convert_inputs.hpp"
#include "denoiser/passes/pack_surface.hpp"
#include "denoiser/passes/validate_inputs.hpp"
#include "hal/error.hpp"

namespace asvgf {
namespace {

using graph::ResourceId;

bool float_format(hal::Format f) {
  switch (f) {
    case hal::Format::R16F:
    case hal::Format::RG16F:
    case hal::Format::RGBA16F:
    case hal::Format::R32F:
    case hal::Format::RG32F:
    case hal::Format::RGBA32F:
      return true;
    default:
      return false;
  }
}

// Throws naming the input when `image` cannot be read as `channels` float channels.
void check_input(const std::string& name, const DenoiserImage& image, std::uint32_t channels) {
  if (!image.image) throw hal::Error(hal::ErrorKind::InvalidUsage, "denoiser input " + name, "no image given");
  if (!float_format(image.format) || hal::format_channels(image.format) < channels)
    throw hal::Error(hal::ErrorKind::InvalidUsage, "denoiser input " + name,
                     "format " + std::string(hal::format_name(image.format)) + " is not a float format with at least " +
                         std::to_string(channels) + " channel(s)");
}

// `wanted`: the formats the shaders write, as the error names them ("rgba32f or rgba16f").
void check_output(const std::string& name, const DenoiserImage& image, std::initializer_list<hal::Format> formats,
                  const std::string& wanted) {
  if (!image.image) throw hal::Error(hal::ErrorKind::InvalidUsage, "denoiser output " + name, "no image given");
  if (std::find(formats.begin(), formats.end(), image.format) == formats.end())
    throw hal::Error(hal::ErrorKind::InvalidUsage, "denoiser output " + name,
                     "format " + std::string(hal::format_name(image.format)) + " given, " + wanted +
                         " needed (a storage image the shader writes)");
}

void check_config(const hal::Device& device, const DenoiserConfig& c) {
  const auto max = device.capabilities().max_image_dimension;
  if (c.width == 0 || c.height == 0 || c.width > max || c.height > max)
    throw hal::Error(
        hal::ErrorKind::InvalidDescriptor, "denoiser size",
        std::to_string(c.width) + "x" + std::to_string(c.height) + " is outside 1.." + std::to_string(max));
  if (const auto problem = check_settings(c.settings))
    throw hal::Error(hal::ErrorKind::InvalidDescriptor, std::string("denoiser setting ") + problem->setting.setting,
                     problem->message());
}

}  // namespace

struct Denoiser::Impl {
  Impl(hal::Device& d, const DenoiserConfig& c) : device(d), config(c), runtime(d), pipelines(d), counters(d) {
    if (c.validate)
      input_counts =
          d.create_buffer({"denoiser input counts", passes::kInputCounts * 4,
                           hal::BufferUsage::Storage | hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst});
  }
  ~Impl() {
    if (input_counts) device.destroy(input_counts);
  }
  hal::Device& device;
  DenoiserConfig config;
  graph::GraphRuntime runtime;
  passes::PipelineCache pipelines;
  passes::SanitizeCounters counters;
  std::unique_ptr<hal::CommandList> own_commands;
  hal::BufferHandle input_counts;  // DenoiserConfig::validate
  hal::State input_counts_state = hal::State::Undefined;
};

Denoiser::Denoiser(hal::Device& device, const DenoiserConfig& config) {
  check_config(device, config);
  impl_ = std::make_unique<Impl>(device, config);
}

Denoiser::~Denoiser() {
  try {
    impl_->device.wait();  // the last frame may still read what the runtime is about to release
  } catch (...) {
    // A lost device has nothing left to wait for.
  }
}

const DenoiserConfig& Denoiser::config() const {
  return impl_->config;
}

InputReport Denoiser::input_report() {
  if (!impl_->config.validate)
    throw hal::Error(hal::ErrorKind::InvalidUsage, "denoiser input report", "DenoiserConfig::validate is off");
  std::array<std::uint32_t, passes::kInputCounts> counts{};
  if (impl_->input_counts_state != hal::State::CopySrc) return api::make_input_report(counts);  // no frame yet
  impl_->device.wait();
  impl_->device.read_buffer(impl_->input_counts, 0, std::as_writable_bytes(std::span(counts)));
  return api::make_input_report(counts);
}

void Denoiser::reset() {
  impl_->runtime.reset_histories();
}

void Denoiser::record(hal::CommandList& commands, const DenoiserInputs& in, const DenoiserOutputs& out) {
  using F = hal::Format;
  const std::uint32_t w = impl_->config.width, h = impl_->config.height;
  check_input("illumination", in.illumination, 3);
  check_input("albedo", in.albedo, 3);
  check_input("normal", in.normal, 3);
  check_input("depth", in.depth, impl_->config.depth_gradient_given ? 2 : 1);
  check_input("motion", in.motion, 2);
  if (in.gradient_samples)
    check_input("gradient_samples", *in.gradient_samples, impl_->config.gradient_current_given ? 3 : 2);
  check_output("radiance", out.radiance, {F::RGBA32F, F::RGBA16F}, "rgba32f or rgba16f");
  if (out.display) check_output("display", *out.display, {F::RGBA8Unorm}, "rgba8");
  // The graph tracks each import's state on its own: one image given twice would be transitioned
  // from a state it is no longer in.
  for (const auto& [name, image] : {std::pair{"illumination", in.illumination},
                                    {"albedo", in.albedo},
                                    {"normal", in.normal},
                                    {"depth", in.depth},
                                    {"motion", in.motion}}) {
    if (image.image == out.radiance.image || (out.display && image.image == out.display->image))
      throw hal::Error(hal::ErrorKind::InvalidUsage, std::string("denoiser input ") + name,
                       "is also an output: denoising in place is not supported");
  }
  if (in.camera_cut) reset();

  graph::RenderGraph g;
  auto import = [&](const char* name, const DenoiserImage& image, std::uint32_t iw, std::uint32_t ih) {
    return g.import(name, image.image, image.state, iw, ih, image.format);
  };
  const std::uint32_t gw = (w + 2) / 3, gh = (h + 2) / 3;
  const ResourceId color = import("illumination", in.illumination, w, h);
  const ResourceId albedo_in = import("albedo", in.albedo, w, h);
  const ResourceId normal = import("normal", in.normal, w, h);
  const ResourceId depth = import("depth", in.depth, w, h);
  const ResourceId motion_in = import("motion", in.motion, w, h);
  const ResourceId radiance = import("radiance", out.radiance, w, h);
  const ResourceId display =
      out.display ? import("display", *out.display, w, h) : g.add_image("display", w, h, F::RGBA8Unorm);
  const ResourceId counters = impl_->counters.import(g);
  const ResourceId depth_normal = g.add_image("depth_normal", w, h, F::RGBA16Uint, graph::Lifetime::Persistent);
  passes::add_pack_surface(g, impl_->pipelines, {depth, normal, depth_normal}, impl_->config.depth_gradient_given);

  // The caller's conventions as the denoiser's, where they differ (radiance in, other motion).
  ResourceId illumination = color, albedo = albedo_in, motion = motion_in;
  const auto& convention = impl_->config.motion;
  if (impl_->config.color_input == ColorInput::Radiance || convention != MotionConvention::ours()) {
    illumination = g.add_image("demodulated", w, h, F::RGBA32F);
    albedo = g.add_image("modulation", w, h, F::R32Uint);  // RGB9E5 words, what the colour was divided by
    motion = g.add_image("motion_pixels", w, h, F::RGBA32F);
    const auto scale = motion_scale(convention, w, h);
    passes::add_convert_inputs(g, impl_->pipelines, {color, albedo_in, motion_in, illumination, albedo, motion},
                               {impl_->config.color_input == ColorInput::Radiance, scale[0], scale[1]});
    // Demodulated colour needs only the motion converted: the caller's colour and albedo are read
    // as they are (the caller divided by its own albedo, not by the pass's RGB9E5 words).
    if (impl_->config.color_input == ColorInput::Demodulated) illumination = color, albedo = albedo_in;
  }

  if (impl_->config.validate) {
    const ResourceId counts =
        g.import_buffer("input_counts", impl_->input_counts, impl_->input_counts_state, passes::kInputCounts * 4);
    passes::add_validate_inputs(g, impl_->pipelines, {color, albedo_in, normal, depth, motion, depth_normal, counts});
    g.output(counts, hal::State::CopySrc);
    impl_->input_counts_state = hal::State::CopySrc;
  }

  std::optional<ResourceId> gradient_samples;
  if (reshades_gradients(impl_->config.method, impl_->config.settings) && in.gradient_samples)
    gradient_samples = import("gradient_samples", *in.gradient_samples, gw, gh);
  passes::add_denoiser(g, impl_->pipelines,
                       {illumination, motion, depth_normal, albedo, counters, radiance, display, gradient_samples,
                        gradient_samples ? "" : "no gradient samples given this frame (nothing moved)",
                        impl_->config.gradient_current_given},
                       impl_->config.settings, impl_->config.method);
  g.output(radiance, out.final_state);
  if (out.display) g.output(display, out.final_state);

  const graph::CompiledFrame frame = impl_->runtime.compile(g);
  impl_->runtime.execute(frame, commands);
}

void Denoiser::denoise(const DenoiserInputs& inputs, const DenoiserOutputs& outputs) {
  if (!impl_->own_commands) impl_->own_commands = impl_->device.create_command_list("asvgf denoiser");
  impl_->own_commands->reset();
  record(*impl_->own_commands, inputs, outputs);
  impl_->device.submit(*impl_->own_commands);
  impl_->device.wait();
}

std::vector<PassTime> Denoiser::timings() {
  return impl_->runtime.timings();
}

SanitisedCounts Denoiser::sanitised() {
  return impl_->counters.read();
}

}  // namespace asvgf
