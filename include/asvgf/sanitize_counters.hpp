// asvgf/sanitize_counters.hpp: the buffer the denoiser's passes count sanitised samples into, for
// callers recording the denoiser into their own render graph (asvgf/denoiser_graph.hpp).
#pragma once

#include <cstdint>

#include "asvgf/denoiser_stats.hpp"
#include "asvgf/render_graph.hpp"

namespace asvgf::passes {

// The buffer the temporal and composite passes count into: samples dropped with a NaN component,
// with an infinite component (and no NaN), finite samples clamped to the fp16 maximum (65504;
// one at it counts too: a half-float input holds no more) before the histories, and output pixels written as 0 because
// their radiance was not finite. Totals since creation.
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
