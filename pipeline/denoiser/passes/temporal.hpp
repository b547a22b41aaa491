// denoiser/passes/temporal.hpp: the `temporal` pass (shaders/denoise/temporal.comp): sanitises this frame's
// samples (NaN/Inf dropped and counted), reprojects last frame's colour and moments, blends them
// with a constant or (with a gradient) adaptive alpha, and tracks the history length.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "asvgf/denoiser_stats.hpp"
#include "denoiser/graph/render_graph.hpp"
#include "denoiser/passes/compute_pass.hpp"
#include "denoiser/passes/denoise_settings.hpp"

namespace asvgf::passes {

struct TemporalResources {
  graph::ResourceId illumination = 0;   // read: RGBA32F demodulated samples of this frame
  graph::ResourceId motion = 0;         // read: RG32F, previous minus current pixel position
  graph::ResourceId depth_normal = 0;   // read, and its history read: persistent RGBA32F
  graph::ResourceId color_history = 0;  // its history read: persistent RGBA16F (rgb, variance)
  graph::ResourceId moments = 0;        // history read and written: persistent RGBA32F (E[l], E[l^2], n, 0)
  graph::ResourceId integrated = 0;     // written: RGBA16F (rgb, temporal variance); may be color_history
  graph::ResourceId counters = 0;       // read-written SanitizeCounters buffer
  std::optional<graph::ResourceId> gradient;  // read: 1/3 res RGBA16F (delta^, Delta^); adaptive alpha
  std::string prefix;                         // of the pass name: "specular." for the second signal
  bool virtual_motion = false;  // `motion` goes through reflections: loose depth test (specular_motion.comp)
};
// Adds "<prefix>temporal". The adaptive variant is used when settings.adaptive and a gradient is given.
// Histories not valid this frame (first frame, GraphRuntime::reset_histories) reset every pixel.
graph::PassBuilder add_temporal(graph::RenderGraph& graph, PipelineCache& pipelines, const TemporalResources& r,
                                const DenoiseSettings& settings);

// The buffer the temporal and composite passes count into: samples dropped with a NaN component,
// with an infinite component (and no NaN), finite samples clamped to the fp16 maximum (65504)
// before the histories, and output pixels written as 0 because their radiance was not finite.
// Totals since creation.
class SanitizeCounters {
 public:
  static constexpr std::uint64_t kSize = 16;
  explicit SanitizeCounters(hal::Device& device);
  ~SanitizeCounters();
  SanitizeCounters(const SanitizeCounters&) = delete;
  SanitizeCounters& operator=(const SanitizeCounters&) = delete;

  // Imports the buffer into this frame's graph as "sanitize_counters" (in the state it was left), as
  // an output that ends the frame in ShaderWrite; call once per graph.
  graph::ResourceId import(graph::RenderGraph& graph);
  // Waits for the device and reads the totals.
  SanitisedCounts read();

 private:
  hal::Device& device_;
  hal::BufferHandle buffer_;
  hal::State state_ = hal::State::CopyDst;
};

}  // namespace asvgf::passes
