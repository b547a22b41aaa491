// Uploading a scene and keeping it current frame after frame.
#include "renderer/scene_gpu.hpp"

#include <cmath>
#include <cstring>

#include "hal/error.hpp"

namespace asvgf::render {
namespace {

float luminance(const glm::vec3& c) {
  return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

template <typename T>
std::span<const std::byte> bytes_of(const std::vector<T>& v) {
  return std::as_bytes(std::span(v));
}

constexpr float kPi = 3.14159265358979f;

}  // namespace

GpuCamera make_camera(const scene::CameraState& c, std::uint32_t width, std::uint32_t height) {
  const glm::vec3 forward = glm::normalize(c.target - c.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_half = std::tan(glm::radians(c.vertical_fov_degrees) * 0.5f);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  return {glm::vec4(c.position, 0), glm::vec4(forward, 0), glm::vec4(right * tan_half * aspect, 0),
          glm::vec4(up * tan_half, 0)};
}

SceneGpu::SceneGpu(hal::Device& device, const scene::Scene& scene, bool ray_query)
    : device_(device), scene_(scene), ray_query_(ray_query) {
  if (ray_query && !device.capabilities().ray_query)
    throw hal::Error(hal::ErrorKind::Unsupported, scene.name,
                     "ray-query tracing asked for on a device without ray queries");
  for (const auto& inst : scene.instances) triangle_count_ += scene.meshes.at(inst.mesh).triangle_count();
  if (triangle_count_ == 0)
    throw hal::Error(hal::ErrorKind::InvalidDescriptor, scene.name, "the scene has no triangles");
  sphere_light_count_ = static_cast<std::uint32_t>(scene.sphere_lights.size());

  const std::uint64_t tri_bytes = std::uint64_t(triangle_count_) * sizeof(GpuTriangle);
  triangles_ = make_buffer("scene.triangles", tri_bytes);
  previous_triangles_ = make_buffer("scene.previous_triangles", tri_bytes);
  std::vector<GpuMaterial> materials;
  for (const auto& m : scene.materials) {
    const bool emissive = m.emission.r > 0 || m.emission.g > 0 || m.emission.b > 0;
    textured_ = textured_ || m.albedo_texture >= 0;
    glossy_ = glossy_ || m.glossy();
    materials.push_back({glm::vec4(m.albedo, static_cast<float>(m.albedo_texture + 1)),
                         glm::vec4(m.emission, emissive ? 1.0f : 0.0f),
                         glm::vec4(m.roughness, m.metallic, m.specular, 0.0f)});
  }
  upload_textures();
  if (materials.empty()) materials.push_back({glm::vec4(0.8f), glm::vec4(0), glm::vec4(1, 0, 0, 0)});
  materials_ = make_buffer("scene.materials", materials.size() * sizeof(GpuMaterial));
  device.upload_buffer(materials_, 0, bytes_of(materials));

  // Lights: every sphere, then every emissive triangle (their count never changes).
  light_count_ = sphere_light_count_;
  for (const auto& inst : scene.instances) {
    const auto& mesh = scene.meshes.at(inst.mesh);
    for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t)
      if (materials.at(mesh.materials.at(t)).emission.w > 0) ++light_count_;
  }
  lights_ = make_buffer("scene.lights", std::max<std::uint64_t>(1, light_count_) * sizeof(GpuLight));
  if (ray_query_) {
    // Boxes, not triangles: the shader's own triangle test decides hits (shaders/common/trace.glsl).
    accel_boxes_ = make_buffer("scene.accel_boxes", std::uint64_t(triangle_count_) * sizeof(TriangleBox),
                               hal::BufferUsage::AccelBuildInput);
    blas_ = device.create_blas(hal::BlasDesc::of_boxes("scene.blas", accel_boxes_, triangle_count_));
    tlas_ = device.create_tlas({"scene.tlas", 1});
  } else {
    // Sized for the worst case of 2n-1 nodes so that rebuilds never reallocate.
    bvh_nodes_ = make_buffer("scene.bvh_nodes", std::uint64_t(2 * triangle_count_) * sizeof(BvhNode));
    bvh_triangles_ = make_buffer("scene.bvh_triangles", std::uint64_t(triangle_count_) * 4);
  }
}

SceneGpu::~SceneGpu() {
  try {
    device_.wait();
    if (tlas_) device_.destroy(tlas_);
    if (blas_) device_.destroy(blas_);
    for (const auto& r : owned_) device_.destroy(hal::BufferHandle{r.id});
  } catch (...) {
    // Nothing to release on a lost device.
  }
}

void SceneGpu::upload_textures() {
  // Texture coordinates per triangle corner, in the same order as world_triangles().
  std::vector<GpuTriangleUv> uvs;
  std::vector<std::uint32_t> texels;
  if (textured_) {
    for (const auto& inst : scene_.instances) {
      const auto& mesh = scene_.meshes.at(inst.mesh);
      for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
        GpuTriangleUv uv{};
        if (!mesh.uvs.empty()) {
          uv.uv0 = mesh.uvs.at(mesh.indices.at(3 * t));
          uv.uv1 = mesh.uvs.at(mesh.indices.at(3 * t + 1));
          uv.uv2 = mesh.uvs.at(mesh.indices.at(3 * t + 2));
        }
        uvs.push_back(uv);
      }
    }
    texels.resize(scene_.textures.size() * 4);  // the table, filled below
    for (std::size_t k = 0; k < scene_.textures.size(); ++k) {
      const auto& tex = scene_.textures[k];
      const GpuTexture entry{static_cast<std::uint32_t>(texels.size()), tex.width, tex.height, 0};
      std::memcpy(&texels[4 * k], &entry, sizeof entry);
      for (std::size_t i = 0; i + 3 < tex.rgba8.size(); i += 4)
        texels.push_back(std::uint32_t(tex.rgba8[i]) | std::uint32_t(tex.rgba8[i + 1]) << 8 |
                         std::uint32_t(tex.rgba8[i + 2]) << 16 | std::uint32_t(tex.rgba8[i + 3]) << 24);
    }
  }
  if (uvs.empty()) uvs.resize(1);
  if (texels.empty()) texels.resize(1);
  triangle_uvs_ = make_buffer("scene.triangle_uvs", uvs.size() * sizeof(GpuTriangleUv));
  texels_ = make_buffer("scene.texels", texels.size() * 4);
  device_.upload_buffer(triangle_uvs_, 0, bytes_of(uvs));
  device_.upload_buffer(texels_, 0, bytes_of(texels));
}

hal::BufferHandle SceneGpu::make_buffer(const char* name, std::uint64_t bytes, hal::BufferUsage extra) {
  const auto b = device_.create_buffer(
      {name, std::max<std::uint64_t>(bytes, 16), hal::BufferUsage::Storage | hal::BufferUsage::CopyDst | extra});
  owned_.push_back(b);
  return b;
}

std::vector<GpuTriangle> SceneGpu::world_triangles(const scene::FrameState& state) const {
  std::vector<GpuTriangle> out;
  out.reserve(triangle_count_);
  for (std::uint32_t i = 0; i < scene_.instances.size(); ++i) {
    const auto& mesh = scene_.meshes.at(scene_.instances[i].mesh);
    const glm::mat4& m = state.instance_transforms.at(i);
    for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
      glm::vec3 p[3];
      for (int k = 0; k < 3; ++k) p[k] = glm::vec3(m * glm::vec4(mesh.positions.at(mesh.indices.at(3 * t + k)), 1.0f));
      out.push_back({p[0], mesh.materials.at(t), p[1], i, p[2], t});
    }
  }
  return out;
}

std::vector<GpuLight> SceneGpu::gpu_lights(const scene::FrameState& state, const scene::FrameState& previous,
                                           const std::vector<GpuTriangle>& triangles) const {
  std::vector<GpuLight> lights;
  std::vector<float> power;
  for (std::size_t i = 0; i < state.lights.size(); ++i) {
    const auto& l = state.lights[i];
    lights.push_back({l.position, l.radius, l.emission, 0, previous.lights.at(i).position, 0, 0, 0});
    power.push_back(luminance(l.emission) * 4.0f * kPi * l.radius * l.radius * kPi);
  }
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const GpuTriangle& tri = triangles[t];
    const auto& m = scene_.materials.at(tri.material);
    if (!(m.emission.r > 0 || m.emission.g > 0 || m.emission.b > 0)) continue;
    const float area = 0.5f * glm::length(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
    lights.push_back({glm::vec3(0), 0, m.emission, 1, glm::vec3(0), 0, t, area});
    power.push_back(luminance(m.emission) * area * kPi);
  }
  double total = 0;
  for (float p : power) total += p;
  for (std::size_t i = 0; i < lights.size(); ++i)
    lights[i].pdf = total > 0 ? static_cast<float>(power[i] / total) : 1.0f / static_cast<float>(lights.size());
  return lights;
}

bool SceneGpu::update(float frame) {
  device_.wait();
  scene::FrameState next = scene::evaluate(scene_, frame);
  const bool moved = first_ || !scene::same_state(next, state_);
  // The BVH (or BLAS) depends on the triangles only: a camera path or a moving light keeps it.
  const bool geometry_moved = first_ || next.instance_transforms != state_.instance_transforms;
  previous_ = first_ ? next : state_;
  state_ = std::move(next);
  std::vector<GpuTriangle> triangles = world_triangles(state_);
  const std::vector<GpuTriangle>& previous = first_ ? triangles : current_triangles_;
  device_.upload_buffer(previous_triangles_, 0, bytes_of(previous));
  device_.upload_buffer(triangles_, 0, bytes_of(triangles));
  const auto lights = gpu_lights(state_, previous_, triangles);
  if (!lights.empty()) device_.upload_buffer(lights_, 0, bytes_of(lights));

  auto commands = device_.create_command_list("scene update");
  commands->begin_label("scene update");
  std::vector<hal::Barrier> to_read = {{triangles_, hal::State::CopyDst, hal::State::ShaderRead},
                                       {previous_triangles_, hal::State::CopyDst, hal::State::ShaderRead}};
  if (!lights.empty()) to_read.push_back({lights_, hal::State::CopyDst, hal::State::ShaderRead});
  if (first_)
    for (auto b : {materials_, triangle_uvs_, texels_})
      to_read.push_back({b, hal::State::CopyDst, hal::State::ShaderRead});
  std::vector<glm::vec3> corners;
  if (geometry_moved) {
    corners.reserve(3 * triangles.size());
    for (const auto& t : triangles) corners.insert(corners.end(), {t.p0, t.p1, t.p2});
  }
  if (geometry_moved && ray_query_) {
    device_.upload_buffer(accel_boxes_, 0, bytes_of(padded_triangle_boxes(corners)));
    const hal::State accel_state = first_ ? hal::State::Undefined : hal::State::AccelRead;
    commands->barrier({{accel_boxes_, hal::State::CopyDst, hal::State::AccelBuildInput},
                       {blas_, accel_state, hal::State::AccelWrite}});
    commands->build_blas(blas_, false);
    commands->barrier(
        {{blas_, hal::State::AccelWrite, hal::State::AccelRead}, {tlas_, accel_state, hal::State::AccelWrite}});
    const hal::TlasInstance instance{blas_};
    commands->build_tlas(tlas_, std::span(&instance, 1), false);
    commands->barrier({tlas_, hal::State::AccelWrite, hal::State::AccelRead});
  } else if (geometry_moved) {
    bvh_ = build_bvh(corners);
    device_.upload_buffer(bvh_nodes_, 0, bytes_of(bvh_.nodes));
    device_.upload_buffer(bvh_triangles_, 0, bytes_of(bvh_.triangles));
    to_read.push_back({bvh_nodes_, hal::State::CopyDst, hal::State::ShaderRead});
    to_read.push_back({bvh_triangles_, hal::State::CopyDst, hal::State::ShaderRead});
  }
  commands->barrier(to_read);
  commands->end_label();
  device_.submit(*commands);
  device_.wait();
  current_triangles_ = std::move(triangles);
  first_ = false;
  return moved;
}

}  // namespace asvgf::render
