// Declaring the passes of one frame for each method.
#include "frame/frame_graph.hpp"

#include "graph/graph_runtime.hpp"
#include "passes/frame_passes.hpp"

namespace asvgf::frame {

using graph::Lifetime;
using graph::ResourceId;
using graph::Use;

std::string_view to_string(Method method) {
  switch (method) {
    case Method::Raw: return "raw";
    case Method::Ema: return "ema";
    case Method::Svgf: return "svgf";
    case Method::Asvgf: return "asvgf";
    case Method::Reference: return "reference";
  }
  return "?";
}

std::optional<Method> method_from_string(std::string_view name) {
  for (Method m : kAllMethods)
    if (to_string(m) == name) return m;
  return std::nullopt;
}

FrameGraphBuilder::FrameGraphBuilder(hal::Device& device) : device_(device), pipelines_cache_(device) {}

FrameGraphBuilder::~FrameGraphBuilder() {
  for (auto& [name, pipeline] : pipelines_) device_.destroy(pipeline);
}

hal::PipelineHandle FrameGraphBuilder::pipeline_for(const graph::RenderGraph& g, const PassSpec& spec) {
  std::string key = spec.name;
  for (const auto& b : spec.bindings) key += "|" + b.name + ":" + std::to_string(int(b.use));
  if (auto it = pipelines_.find(key); it != pipelines_.end()) return it->second;
  auto& bindings = bindings_.emplace_back();
  std::uint32_t index = 0;
  for (const auto& b : spec.bindings) {
    const bool image = g.resource(b.resource).kind == hal::ResourceKind::Image;
    hal::ShaderBinding sb;
    sb.binding = index++;
    sb.name = names_.emplace_back(b.name);
    sb.access = graph::writes(b.use) ? (graph::reads(b.use) ? hal::Access::ReadWrite : hal::Access::Write)
                                     : hal::Access::Read;
    sb.kind = b.use == Use::AccelRead ? hal::BindingKind::AccelerationStructure
              : !image                ? hal::BindingKind::StorageBuffer
              : sb.access == hal::Access::Read ? hal::BindingKind::SampledImage
                                               : hal::BindingKind::StorageImage;
    bindings.push_back(sb);
  }
  hal::ShaderInfo& info = shaders_.emplace_back();
  info.name = names_.emplace_back(spec.name + " (declared bindings)");
  info.bindings = bindings;
  info.workgroup_size = {8, 8, 1};
  auto pipeline = device_.create_pipeline({spec.name, &info});
  pipelines_.emplace(key, pipeline);
  return pipeline;
}

void FrameGraphBuilder::add(graph::RenderGraph& g, PassSpec spec, std::uint32_t width, std::uint32_t height,
                            std::string skip_reason) {
  auto builder = g.add_pass(spec.name);
  for (const auto& b : spec.bindings) {
    if (b.history) builder.read_history(b.resource);
    else if (b.optional) builder.read_optional(b.resource);
    else if (graph::writes(b.use)) builder.write(b.resource, b.use);
    else builder.read(b.resource, b.use);
  }
  builder.skip_if(!skip_reason.empty(), skip_reason);
  const hal::PipelineHandle pipeline = skip_reason.empty() ? pipeline_for(g, spec) : hal::PipelineHandle{};
  // The pass binds what its shader needs, independently of the declarations above: a declaration
  // missing from the graph then shows up as a hazard on the recording HAL.
  builder.execute([pipeline, spec, width, height](graph::PassContext& ctx) {
    std::vector<hal::BindingSetDesc::Entry> entries;
    for (const auto& b : spec.bindings)
      entries.push_back({b.name, b.history ? ctx.history(b.resource) : ctx.resource(b.resource)});
    ctx.dispatch(pipeline, entries, {}, (width + 7) / 8, (height + 7) / 8);
  });
  specs_.push_back(std::move(spec));
}

graph::RenderGraph FrameGraphBuilder::build(const FrameSettings& s, const render::SceneGpu& scene_gpu,
                                            const FrameTargets& targets) {
  specs_.clear();
  graph::RenderGraph g;
  const std::uint32_t w = s.width, h = s.height;
  const std::uint32_t gw = (w + 2) / 3, gh = (h + 2) / 3;  // one gradient sample per 3x3 stratum
  using F = hal::Format;

  const passes::SceneInputs scene = passes::import_scene(g, scene_gpu, w, h);
  const ResourceId hdr = g.import("hdr", targets.hdr, targets.hdr_state);
  const ResourceId display = g.import("display", targets.display, targets.display_state);
  // Persistent: read next frame as histories.
  const ResourceId vbuffer = g.add_image("visibility", w, h, F::RGBA32Uint, Lifetime::Persistent);
  const ResourceId depth_normal = g.add_image("depth_normal", w, h, F::RGBA32F, Lifetime::Persistent);
  const ResourceId seeds = g.add_image("rng_seed", w, h, F::R32Uint, Lifetime::Persistent);
  const ResourceId illumination = g.add_image("illumination", w, h, F::RGBA32F, Lifetime::Persistent);
  // Transient.
  const ResourceId motion = g.add_image("motion", w, h, F::RG32F);
  const ResourceId albedo = g.add_image("albedo", w, h, F::RGBA16F);

  passes::add_gbuffer(g, pipelines_cache_, scene, {vbuffer, depth_normal, motion, albedo}, w, h);

  const bool adaptive = s.method == Method::Asvgf;
  const std::string not_moved = "nothing in the scene, camera or lights moved since the last frame";
  const bool gradients = adaptive && s.scene_moved;
  ResourceId gradient_seeds = 0, gradient_prev = 0, gradient_final = 0;
  if (adaptive) {
    gradient_seeds = g.add_image("gradient_seeds", w, h, F::RGBA32Uint);
    gradient_prev = g.add_image("gradient_prev_luminance", gw, gh, F::RG32F);
    const ResourceId claims = g.add_buffer("gradient_claims", std::uint64_t(gw) * gh * 4);
    passes::add_gradient_select(g, pipelines_cache_, scene,
                                {vbuffer, seeds, illumination, depth_normal, claims, gradient_seeds, gradient_prev},
                                s.frame, w, h, gradients ? "" : not_moved);
  }
  passes::add_pathtrace(g, pipelines_cache_, scene, vbuffer,
                        gradients ? std::optional<ResourceId>(gradient_seeds) : std::nullopt, illumination, seeds,
                        {s.frame, s.seed, s.max_bounces, s.spp}, w, h);
  if (adaptive) {
    ResourceId current = g.add_image("gradient", gw, gh, F::RG16F);
    add(g, {"gradient", {{"illumination", illumination, Use::ShaderRead}, {"gradient_prev", gradient_prev, Use::ShaderRead},
                         {"visibility", vbuffer, Use::ShaderRead}, {"gradient", current, Use::ShaderWrite}}},
        gw, gh, gradients ? "" : not_moved);
    for (int i = 0; i < s.gradient_iterations; ++i) {
      const ResourceId next = g.add_image("gradient." + std::to_string(i + 1), gw, gh, F::RG16F);
      add(g, {"gradient_atrous." + std::to_string(i + 1),
              {{"gradient_in", current, Use::ShaderRead}, {"depth_normal", depth_normal, Use::ShaderRead},
               {"gradient_out", next, Use::ShaderWrite}}},
          gw, gh, gradients ? "" : not_moved);
      current = next;
    }
    gradient_final = current;
  }

  ResourceId final_illumination = illumination;
  if (s.method == Method::Reference) {
    const ResourceId accum = g.add_image("accumulation", w, h, F::RGBA32F, Lifetime::Persistent);
    passes::add_accumulate(g, pipelines_cache_, illumination, accum, s.accumulation_valid, w, h);
    final_illumination = accum;
  } else if (s.method != Method::Raw) {
    const ResourceId color_history = g.add_image("color_history", w, h, F::RGBA16F, Lifetime::Persistent);
    const ResourceId moments = g.add_image("moments", w, h, F::RG16F, Lifetime::Persistent);
    const ResourceId length = g.add_image("history_length", w, h, F::R16F, Lifetime::Persistent);
    const bool spatial = s.method != Method::Ema && s.atrous_iterations > 0;
    const ResourceId integrated = spatial ? g.add_image("integrated", w, h, F::RGBA16F) : color_history;
    PassSpec temporal{"temporal", {{"illumination", illumination, Use::ShaderRead}, {"motion", motion, Use::ShaderRead},
                                   {"depth_normal", depth_normal, Use::ShaderRead},
                                   {"prev_depth_normal", depth_normal, Use::ShaderRead, true},
                                   {"prev_color", color_history, Use::ShaderRead, true},
                                   {"prev_moments", moments, Use::ShaderRead, true},
                                   {"prev_history_length", length, Use::ShaderRead, true},
                                   {"integrated", integrated, Use::ShaderWrite}, {"moments", moments, Use::ShaderWrite},
                                   {"history_length", length, Use::ShaderWrite}}};
    if (gradients)
      temporal.bindings.push_back({"gradient", gradient_final, Use::ShaderRead, false, true});
    add(g, temporal, w, h);
    final_illumination = integrated;
    if (spatial) {
      ResourceId current = g.add_image("color_variance", w, h, F::RGBA16F);
      add(g, {"variance", {{"integrated", integrated, Use::ShaderRead}, {"moments", moments, Use::ShaderRead},
                           {"history_length", length, Use::ShaderRead}, {"depth_normal", depth_normal, Use::ShaderRead},
                           {"color_variance", current, Use::ShaderWrite}}},
          w, h);
      for (int i = 0; i < s.atrous_iterations; ++i) {
        const ResourceId next = g.add_image("atrous." + std::to_string(i + 1), w, h, F::RGBA16F);
        PassSpec atrous{"atrous." + std::to_string(i + 1),
                        {{"color_in", current, Use::ShaderRead}, {"depth_normal", depth_normal, Use::ShaderRead},
                         {"color_out", next, Use::ShaderWrite}}};
        if (i == s.history_tap) atrous.bindings.push_back({"color_history", color_history, Use::ShaderWrite});
        add(g, atrous, w, h);
        current = next;
      }
      final_illumination = current;
    }
  }

  add(g, {"composite", {{"illumination", final_illumination, Use::ShaderRead}, {"albedo", albedo, Use::ShaderRead},
                        {"hdr", hdr, Use::ShaderWrite}, {"display", display, Use::ShaderWrite}}},
      w, h);
  g.output(hdr, hal::State::CopySrc);
  g.output(display, hal::State::CopySrc);

  // The intermediate-buffer view is an output only when asked for; otherwise it is culled.
  const ResourceId debug = g.add_image("debug_view", w, h, F::RGBA8Unorm);
  add(g, {"debug_view", {{"depth_normal", depth_normal, Use::ShaderRead}, {"motion", motion, Use::ShaderRead},
                         {"debug_view", debug, Use::ShaderWrite}}},
      w, h);
  if (s.debug_view) g.output(debug);
  return g;
}

}  // namespace asvgf::frame
