// The noisy-input passes: each fills its shader's generated uniform struct.
#include "renderer/render_passes.hpp"

#include "hal/error.hpp"

#include "shaders/accumulate.hpp"
#include "shaders/debug_view.hpp"
#include "shaders/gbuffer.rayquery.hpp"
#include "shaders/gbuffer.software.hpp"
#include "shaders/gradient_clear.hpp"
#include "shaders/gradient_resolve.hpp"
#include "shaders/gradient_select.hpp"
#include "shaders/pathtrace.rayquery.hpp"
#include "shaders/pathtrace.rayquery_carried.hpp"
#include "shaders/pathtrace.rayquery_carried_only.hpp"
#include "shaders/pathtrace.rayquery_full_range.hpp"
#include "shaders/pathtrace.rayquery_split.hpp"
#include "shaders/pathtrace.software.hpp"
#include "shaders/pathtrace.software_carried.hpp"
#include "shaders/pathtrace.software_carried_only.hpp"
#include "shaders/pathtrace.software_full_range.hpp"
#include "shaders/pathtrace.software_split.hpp"
#include "shaders/specular_motion.hpp"

namespace asvgf::passes {
namespace {

// Every variant of a shader has the same uniform block: one generated struct serves them all.
using GbufferParams = shaders::gbuffer_software_uniforms::Params;
using PathtraceParams = shaders::pathtrace_software_uniforms::Params;
using GradientClearParams = shaders::gradient_clear_uniforms::Params;
using GradientSelectParams = shaders::gradient_select_uniforms::Params;
using GradientResolveParams = shaders::gradient_resolve_uniforms::Params;
using AccumulateParams = shaders::accumulate_uniforms::Params;
using DebugViewParams = shaders::debug_view_uniforms::Params;

// The camera as a shader's generated Camera struct.
template <typename Camera>
Camera uniform_camera(const render::GpuCamera& c) {
  const auto v = [](const glm::vec4& x) { return std::array<float, 4>{x.x, x.y, x.z, x.w}; };
  return {v(c.position), v(c.forward), v(c.right), v(c.up)};
}

// The scene buffers `shader` actually binds (the optimiser drops unused ones).
std::vector<Binding> scene_bindings(const SceneInputs& s, const hal::ShaderInfo& shader) {
  std::vector<Binding> all = {{"triangles", s.triangles},       {"previous_triangles", s.previous_triangles},
                              {"materials", s.materials},       {"lights", s.lights},
                              {"triangle_uvs", s.triangle_uvs}, {"texels", s.texels}};
  if (s.ray_query)
    all.push_back({"scene", s.tlas});
  else
    all.insert(all.end(), {{"bvh_nodes", s.bvh_nodes}, {"bvh_triangles", s.bvh_triangles}});
  std::vector<Binding> used;
  for (auto& b : all)
    if (shader.find(b.name)) used.push_back(std::move(b));
  return used;
}

}  // namespace

SceneInputs import_scene(graph::RenderGraph& graph, const render::SceneGpu& scene, std::uint32_t width,
                         std::uint32_t height) {
  SceneInputs s;
  s.ray_query = scene.ray_query();
  const auto read = hal::State::ShaderRead;
  if (s.ray_query) {
    s.tlas = graph.import("scene.tlas", scene.tlas(), hal::State::AccelRead);
  } else {
    s.bvh_nodes = graph.import("scene.bvh_nodes", scene.bvh_nodes(), read);
    s.bvh_triangles = graph.import("scene.bvh_triangles", scene.bvh_triangles(), read);
  }
  s.triangles = graph.import("scene.triangles", scene.triangles(), read);
  s.previous_triangles = graph.import("scene.previous_triangles", scene.previous_triangles(), read);
  s.materials = graph.import("scene.materials", scene.materials(), read);
  s.lights = graph.import("scene.lights", scene.lights(), read);
  s.triangle_uvs = graph.import("scene.triangle_uvs", scene.triangle_uvs(), read);
  s.texels = graph.import("scene.texels", scene.texels(), read);
  s.light_count = scene.light_count();
  s.sphere_count = scene.sphere_light_count();
  s.camera = render::make_camera(scene.state().camera, width, height);
  s.previous_camera = render::make_camera(scene.previous_state().camera, width, height);
  return s;
}

void add_gbuffer(graph::RenderGraph& graph, PipelineCache& pipelines, const SceneInputs& scene, const GbufferTargets& t,
                 std::uint32_t width, std::uint32_t height, bool demodulate) {
  const hal::ShaderInfo& shader = scene.ray_query ? shaders::gbuffer_rayquery : shaders::gbuffer_software;
  using Camera = shaders::gbuffer_software_uniforms::Camera;
  const GbufferParams params{uniform_camera<Camera>(scene.camera),
                             uniform_camera<Camera>(scene.previous_camera),
                             width,
                             height,
                             scene.sphere_count,
                             !demodulate             ? 0u
                             : t.diffuse_albedo_only ? 2u
                                                     : 1u};
  auto bindings = scene_bindings(scene, shader);
  bindings.insert(
      bindings.end(),
      {{"visibility", t.visibility}, {"depth_normal", t.depth_normal}, {"motion", t.motion}, {"albedo", t.albedo}});
  add_compute_pass(graph, "gbuffer", shader, pipelines.get<decltype(params)>(shader), std::move(bindings),
                   to_bytes(params), {width, height, 1});
}

PathtraceParams pathtrace_params(const SceneInputs& scene, const PathtraceSettings& s, std::uint32_t width,
                                 std::uint32_t height, bool luminance_in_alpha) {
  return {uniform_camera<shaders::pathtrace_software_uniforms::Camera>(scene.camera),
          width,
          height,
          s.frame,
          s.seed,
          scene.light_count,
          scene.sphere_count,
          s.max_bounces,
          s.spp,
          s.demodulate ? 1u : 0u,
          luminance_in_alpha ? 1u : 0u};
}

void add_pathtrace(graph::RenderGraph& graph, PipelineCache& pipelines, const SceneInputs& scene,
                   graph::ResourceId visibility, graph::ResourceId albedo, graph::ResourceId illumination,
                   graph::ResourceId gradient_candidates, graph::ResourceId ray_counter, const PathtraceSettings& s,
                   std::uint32_t width, std::uint32_t height, const std::string& name,
                   std::optional<SpecularTargets> specular, std::optional<CarriedSampleTargets> carried) {
  if (s.full_range && (specular || carried))
    throw hal::Error(hal::ErrorKind::InvalidUsage, name,
                     "full-range (fp32) illumination is for unfiltered output: no split signals or carried samples");
  const bool rq = scene.ray_query;
  const std::uint32_t strata_w = groups_for(width, 3), strata_h = groups_for(height, 3);
  const bool carried_apart = carried && specular;  // the split variant has no storage image to spare
  if (carried_apart) {
    const hal::ShaderInfo& shader =
        rq ? shaders::pathtrace_rayquery_carried_only : shaders::pathtrace_software_carried_only;
    const PathtraceParams params = pathtrace_params(scene, s, width, height, carried->luminance_in_alpha);
    auto bindings = scene_bindings(scene, shader);
    bindings.insert(bindings.end(), {{"gradient_seeds", carried->carried.seeds},
                                     {"gradient_prev", carried->carried.prev},
                                     {"gradient_samples", carried->gradient_samples},
                                     {"ray_counter", ray_counter}});
    add_compute_pass(graph, name + "_carried", shader, pipelines.get<decltype(params)>(shader), std::move(bindings),
                     to_bytes(params), {strata_w, strata_h, 1})
        .skip_if(!carried->skip_reason.empty(), carried->skip_reason);
  }
  // Carried samples in the same dispatch where they are shaded at all this frame.
  const bool merged = carried && !carried_apart && carried->skip_reason.empty();
  const hal::ShaderInfo& shader =
      s.full_range ? (rq ? shaders::pathtrace_rayquery_full_range : shaders::pathtrace_software_full_range)
      : specular   ? (rq ? shaders::pathtrace_rayquery_split : shaders::pathtrace_software_split)
      : merged     ? (rq ? shaders::pathtrace_rayquery_carried : shaders::pathtrace_software_carried)
                   : (rq ? shaders::pathtrace_rayquery : shaders::pathtrace_software);
  const PathtraceParams params = pathtrace_params(scene, s, width, height, merged && carried->luminance_in_alpha);
  auto bindings = scene_bindings(scene, shader);
  bindings.insert(bindings.end(), {{"visibility", visibility},
                                   {"albedo", albedo},
                                   {"illumination", illumination},
                                   {"gradient_candidates", gradient_candidates},
                                   {"ray_counter", ray_counter}});
  if (specular)
    bindings.insert(bindings.end(), {{"specular", specular->signal}, {"specular_albedo", specular->albedo}});
  std::uint32_t invocation_rows = height;
  if (merged) {
    bindings.insert(bindings.end(), {{"gradient_seeds", carried->carried.seeds},
                                     {"gradient_prev", carried->carried.prev},
                                     {"gradient_samples", carried->gradient_samples}});
    // pathtrace.comp's layout: 8x8 workgroups; past the image's rows, one 8x8 tile of strata each.
    const std::uint32_t groups_x = groups_for(width, 8);
    const std::uint32_t tiles = groups_for(strata_w, 8) * groups_for(strata_h, 8);
    invocation_rows = groups_for(height, 8) * 8 + groups_for(tiles, groups_x) * 8;
  }
  add_compute_pass(graph, name, shader, pipelines.get<decltype(params)>(shader), std::move(bindings), to_bytes(params),
                   {width, invocation_rows, 1});
}

graph::ResourceId add_gradient_candidates_image(graph::RenderGraph& graph, std::uint32_t width, std::uint32_t height) {
  return graph.add_image("gradient_candidates", 2 * groups_for(width, 3), groups_for(height, 3),
                         hal::Format::RGBA32Uint, graph::Lifetime::Persistent);
}

void add_gradient_select(graph::RenderGraph& graph, PipelineCache& pipelines, const SceneInputs& scene,
                         const GradientSelectTargets& t, std::uint32_t width, std::uint32_t height,
                         const std::string& skip_reason) {
  const std::uint32_t sw = groups_for(width, 3), sh = groups_for(height, 3);
  const GradientClearParams clear{width, height, sw, sh};
  add_compute_pass(graph, "gradient_clear", shaders::gradient_clear,
                   pipelines.get<GradientClearParams>(shaders::gradient_clear),
                   {{"claims", t.claims}, {"gradient_prev", t.carried.prev}}, to_bytes(clear), {sw, sh, 1})
      .skip_if(!skip_reason.empty(), skip_reason);
  // Bids, then the winners write: the lowest bid wins whatever order invocations run in.
  const GradientSelectParams select{uniform_camera<shaders::gradient_select_uniforms::Camera>(scene.camera), width,
                                    height, sw, sh};
  const GradientResolveParams resolve{uniform_camera<shaders::gradient_resolve_uniforms::Camera>(scene.camera), width,
                                      height, sw, sh};
  add_compute_pass(graph, "gradient_select", shaders::gradient_select,
                   pipelines.get<GradientSelectParams>(shaders::gradient_select),
                   {{"triangles", scene.triangles},
                    {"gradient_candidates", t.candidates, true},
                    {"depth_normal", t.depth_normal},
                    {"claims", t.claims}},
                   to_bytes(select), {sw, sh, 1})
      .skip_if(!skip_reason.empty(), skip_reason);
  add_compute_pass(graph, "gradient_resolve", shaders::gradient_resolve,
                   pipelines.get<GradientResolveParams>(shaders::gradient_resolve),
                   {{"triangles", scene.triangles},
                    {"gradient_candidates", t.candidates, true},
                    // No depth_normal: a winner passed its tests in gradient_select already.
                    {"claims", t.claims},
                    // Written only where a sample landed: elsewhere gradient_prev keeps gradient_clear's -1
                    // and the seeds are undefined (pathtrace reads them only where gradient_prev.y names a pixel).
                    {"gradient_seeds", t.carried.seeds},
                    {"gradient_prev", t.carried.prev}},
                   to_bytes(resolve), {sw, sh, 1})
      .skip_if(!skip_reason.empty(), skip_reason);
}

void add_specular_motion(graph::RenderGraph& graph, PipelineCache& pipelines, const SceneInputs& scene,
                         graph::ResourceId depth_normal, graph::ResourceId motion, graph::ResourceId specular,
                         graph::ResourceId target, std::uint32_t width, std::uint32_t height) {
  using Params = shaders::specular_motion_uniforms::Params;
  using Camera = shaders::specular_motion_uniforms::Camera;
  const Params params{
      uniform_camera<Camera>(scene.camera), uniform_camera<Camera>(scene.previous_camera), width, height, 0, 0};
  add_compute_pass(
      graph, "specular_motion", shaders::specular_motion, pipelines.get<Params>(shaders::specular_motion),
      {{"depth_normal", depth_normal}, {"motion", motion}, {"specular", specular}, {"specular_motion", target}},
      to_bytes(params), {width, height, 1});
}

void add_accumulate(graph::RenderGraph& graph, PipelineCache& pipelines, graph::ResourceId illumination,
                    graph::ResourceId accumulation, bool history_valid, std::uint32_t width, std::uint32_t height) {
  const AccumulateParams params{width, height, history_valid ? 1u : 0u, 0};
  add_compute_pass(
      graph, "accumulate", shaders::accumulate, pipelines.get<AccumulateParams>(shaders::accumulate),
      {{"illumination", illumination}, {"prev_accumulation", accumulation, true}, {"accumulation", accumulation}},
      to_bytes(params), {width, height, 1});
}

void add_debug_view(graph::RenderGraph& graph, PipelineCache& pipelines, const DebugViewInputs& in, DebugView view,
                    std::uint32_t width, std::uint32_t height) {
  // Images the method lacks are bound to an input of the same kind that is always there (the moments,
  // R32Uint words, to the unsigned depth_normal; the others to the noisy input) and flagged unavailable.
  const std::uint32_t available = (in.gradient ? 1u : 0u) | (in.moments ? 2u : 0u) | (in.variance ? 4u : 0u);
  const DebugViewParams params{width,
                               height,
                               static_cast<std::uint32_t>(view),
                               0.25f,
                               in.denoise.alpha,
                               in.denoise.history_cap,
                               available,
                               in.denoise.antilag};
  add_compute_pass(graph, "debug_view", shaders::debug_view, pipelines.get<DebugViewParams>(shaders::debug_view),
                   {{"depth_normal", in.depth_normal},
                    {"motion", in.motion},
                    {"albedo", in.albedo},
                    {"illumination", in.illumination},
                    {"gradient", in.gradient.value_or(in.illumination)},
                    {"moments", in.moments.value_or(in.depth_normal)},
                    {"variance", in.variance.value_or(in.illumination)},
                    {"debug_view", in.target}},
                   to_bytes(params), {width, height, 1});
}

}  // namespace asvgf::passes
