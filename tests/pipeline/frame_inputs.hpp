// Test helper: runs the visibility and path-tracing passes of one frame on a device and reads back
// every image they write, for checks against analytic results.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "asvgf/graph_runtime.hpp"
#include "cpu_oracle/depth_normal.hpp"
#include "cpu_oracle/rgb9e5.hpp"
#include "renderer/render_passes.hpp"
#include "renderer/scene/scene.hpp"
#include "renderer/scene_gpu.hpp"

// A half float's value (subnormals included).
inline float half_to_float(std::uint16_t h) {
  const int e = (h >> 10) & 0x1f, m = h & 0x3ff;
  const float v = e == 0 ? std::ldexp(float(m), -24) : std::ldexp(float(m | 0x400), e - 25);
  return (h & 0x8000) ? -v : v;
}

struct FrameInputs {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint32_t> visibility;  // 4 per pixel
  // 4 per pixel; motion and illumination widened from the half floats the frame keeps them in
  std::vector<float> depth_normal, motion, illumination;
  std::vector<float> albedo;  // 4 per pixel: the RGB9E5 words' rgb (what the path tracer divided by), 1
  // With `split`: pathtrace's second signal and its albedo; `illumination` and `albedo` are then
  // the diffuse ones.
  std::vector<float> specular, specular_motion;  // specular.a: the first specular ray's length
  std::vector<std::uint16_t> specular_albedo;
};

// Renders frames 0..`frame` of `scene` (so that "previous" is frame-1) and returns frame `frame`'s
// inputs. `spp` samples per pixel, `max_bounces`, `seed` as in the path tracer; `split`: diffuse and
// specular signals apart (the frame's choice on glossy scenes).
inline FrameInputs render_frame_inputs(hal::Device& device, const asvgf::scene::Scene& scene, bool ray_query,
                                       std::uint32_t width, std::uint32_t height, int frame, std::uint32_t spp = 1,
                                       std::uint32_t max_bounces = 4, std::uint32_t seed = 7, bool split = false) {
  using namespace asvgf;
  render::SceneGpu gpu(device, scene, ray_query);
  graph::GraphRuntime runtime(device);
  passes::PipelineCache pipelines(device);
  const auto usage = hal::ImageUsage::Storage | hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc;
  struct Target {
    const char* name;
    hal::Format format;
    hal::ImageHandle image;
  };
  Target targets[] = {{"visibility", hal::Format::RGBA32Uint, {}},   {"depth_normal", hal::Format::RGBA16Uint, {}},
                      {"motion", hal::Format::R32Uint, {}},          {"albedo", hal::Format::R32Uint, {}},
                      {"illumination", hal::Format::RGBA16F, {}},    {"specular", hal::Format::RGBA32F, {}},
                      {"specular_albedo", hal::Format::RGBA16F, {}}, {"specular_motion", hal::Format::RGBA32F, {}}};
  for (auto& t : targets) t.image = device.create_image({t.name, width, height, t.format, usage});
  const auto ray_counter =
      device.create_buffer({"ray_counter", 16, hal::BufferUsage::Storage | hal::BufferUsage::CopyDst});
  const std::uint32_t zeros[4] = {};
  device.upload_buffer(ray_counter, 0, std::as_bytes(std::span(zeros)));
  auto commands = device.create_command_list("frame inputs");
  for (int f = 0; f <= frame; ++f) {
    gpu.update(static_cast<float>(f));
    if (f < frame) continue;  // only the last frame is rendered; earlier updates set "previous"
    graph::RenderGraph g;
    const auto scene_in = passes::import_scene(g, gpu, width, height);
    const int count = split ? 8 : 5;
    graph::ResourceId ids[8];
    for (int i = 0; i < count; ++i)
      ids[i] = g.import(targets[i].name, targets[i].image, hal::State::Undefined, width, height);
    const auto candidates = passes::add_gradient_candidates_image(g, width, height);
    const auto rays = g.import("ray_counter", ray_counter, hal::State::CopyDst);
    passes::add_gbuffer(g, pipelines, scene_in, {ids[0], ids[1], ids[2], ids[3], split}, width, height);
    passes::add_pathtrace(g, pipelines, scene_in, ids[0], ids[3], ids[4], candidates, rays,
                          {static_cast<std::uint32_t>(frame), seed, max_bounces, spp}, width, height, "pathtrace",
                          split ? std::optional(passes::SpecularTargets{ids[5], ids[6]}) : std::nullopt);
    if (split) passes::add_specular_motion(g, pipelines, scene_in, ids[1], ids[2], ids[5], ids[7], width, height);
    for (int i = 0; i < count; ++i) g.output(ids[i], hal::State::CopySrc);
    auto compiled = runtime.compile(g);
    runtime.execute(compiled, *commands);
    device.submit(*commands);
    device.wait();
  }
  FrameInputs out;
  out.width = width;
  out.height = height;
  const std::size_t n = std::size_t(width) * height * 4;
  auto read = [&](int target, auto& values) {
    values.resize(n);
    device.read_image(targets[target].image, std::as_writable_bytes(std::span(values)));
  };
  read(0, out.visibility);
  {  // the 8-byte texel (shaders/common/depth_normal.glsl) as (z, dz, octahedral x, y)
    std::vector<std::uint16_t> texels;
    read(1, texels);
    out.depth_normal.resize(n);
    for (std::size_t i = 0; i < n; i += 4) {
      const auto v = asvgf::reference::unpack_depth_normal({texels[i], texels[i + 1], texels[i + 2], texels[i + 3]});
      out.depth_normal[i] = v.z, out.depth_normal[i + 1] = v.dz;
      out.depth_normal[i + 2] = v.oct[0], out.depth_normal[i + 3] = v.oct[1];
    }
  }
  auto read_halves = [&](int target, std::vector<float>& values) {
    std::vector<std::uint16_t> halves;
    read(target, halves);
    values.resize(n);
    for (std::size_t i = 0; i < n; ++i) values[i] = half_to_float(halves[i]);
  };
  {  // x, y as two halves a word (shaders/common/motion.glsl)
    std::vector<std::uint16_t> halves(std::size_t(width) * height * 2);
    device.read_image(targets[2].image, std::as_writable_bytes(std::span(halves)));
    out.motion.assign(n, 0.0f);
    for (std::size_t i = 0; i < std::size_t(width) * height; ++i) {
      out.motion[4 * i] = half_to_float(halves[2 * i]);
      out.motion[4 * i + 1] = half_to_float(halves[2 * i + 1]);
    }
  }
  {
    std::vector<std::uint32_t> words(std::size_t(width) * height);
    device.read_image(targets[3].image, std::as_writable_bytes(std::span(words)));
    out.albedo.resize(n);
    for (std::size_t i = 0; i < words.size(); ++i) {
      const auto rgb = asvgf::reference::unpack_rgb9e5(words[i]);
      for (int c = 0; c < 3; ++c) out.albedo[4 * i + c] = static_cast<float>(rgb[c]);
      out.albedo[4 * i + 3] = 1.0f;
    }
  }
  read_halves(4, out.illumination);
  if (split) {
    read(5, out.specular);
    read(6, out.specular_albedo);
    read(7, out.specular_motion);
  }
  commands.reset();
  for (auto& t : targets) device.destroy(t.image);
  device.destroy(ray_counter);
  return out;
}
