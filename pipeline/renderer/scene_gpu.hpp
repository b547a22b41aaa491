// renderer/scene_gpu.hpp: a scene on the GPU, through the HAL: world-space triangles of this frame and
// the previous one, materials, lights, and what tracing needs (a BLAS + TLAS for the ray-query
// variant, a SAH BVH for the software variant). Layouts match shaders/common/scene_data.glsl.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "hal/device.hpp"
#include "renderer/bvh.hpp"
#include "renderer/scene/scene.hpp"

namespace asvgf::render {

// std430 layouts shared with shaders/common/scene_data.glsl.
struct GpuTriangle {
  glm::vec3 p0;
  std::uint32_t material;
  glm::vec3 p1;
  std::uint32_t instance;
  glm::vec3 p2;
  std::uint32_t primitive;  // triangle index within its mesh
};
struct GpuMaterial {
  glm::vec4 albedo;    // rgb, a = albedo texture index + 1 (0: untextured)
  glm::vec4 emission;  // rgb radiance, a = 1 when emissive
  glm::vec4 surface;   // roughness, metallic, specular, 0
};
// Texture coordinates of a triangle's corners (zeros for meshes without uvs).
struct GpuTriangleUv {
  glm::vec2 uv0, uv1, uv2;
  glm::vec2 pad{0.0f};
};
// The texel buffer starts with one of these per texture (4 uints each), then the texels: RGBA8
// sRGB, one uint per texel, row-major. One buffer, not two: WebGPU allows 8 storage buffers a stage.
struct GpuTexture {
  std::uint32_t offset, width, height, pad;  // offset: in uints from the buffer's start
};
struct GpuLight {
  glm::vec3 position;       // sphere centre
  float radius;             // sphere radius
  glm::vec3 emission;       // radiance
  std::uint32_t type;       // 0 sphere, 1 emissive triangle
  glm::vec3 prev_position;  // sphere centre last frame
  float pdf;                // probability of picking this light for next-event estimation
  std::uint32_t triangle;   // emissive triangle: its index in the triangle buffer
  float area;               // emissive triangle: its area
  std::uint32_t pad0 = 0, pad1 = 0;
};
static_assert(sizeof(GpuTriangle) == 48 && sizeof(GpuMaterial) == 48 && sizeof(GpuLight) == 64);
static_assert(sizeof(GpuTriangleUv) == 32 && sizeof(GpuTexture) == 16);

// Camera as the shaders use it: a primary ray through pixel p is
// normalize(forward + ((2(p.x+0.5)/w) - 1) * right + (1 - 2(p.y+0.5)/h) * up).
struct GpuCamera {
  glm::vec4 position;  // w unused
  glm::vec4 forward;   // unit
  glm::vec4 right;     // scaled by tan(fov/2) * aspect
  glm::vec4 up;        // scaled by tan(fov/2)
};
GpuCamera make_camera(const scene::CameraState& camera, std::uint32_t width, std::uint32_t height);

class SceneGpu {
 public:
  // `ray_query` selects the tracing variant: acceleration structures, or the software BVH.
  SceneGpu(hal::Device& device, const scene::Scene& scene, bool ray_query);
  ~SceneGpu();
  SceneGpu(const SceneGpu&) = delete;
  SceneGpu& operator=(const SceneGpu&) = delete;

  // Evaluates the scene at `frame` and uploads it; the previous update becomes "previous". Returns
  // whether anything (camera, instances, lights) changed since the previous update. Waits for the
  // device: call between frames.
  bool update(float frame);

  bool ray_query() const { return ray_query_; }
  const scene::FrameState& state() const { return state_; }
  const scene::FrameState& previous_state() const { return previous_; }
  std::uint32_t triangle_count() const { return triangle_count_; }
  std::uint32_t light_count() const { return light_count_; }
  std::uint32_t sphere_light_count() const { return sphere_light_count_; }
  const Bvh& bvh() const { return bvh_; }

  // All in State::ShaderRead after update() (the TLAS in AccelRead); import them into the graph.
  hal::BufferHandle triangles() const { return triangles_; }
  hal::BufferHandle previous_triangles() const { return previous_triangles_; }
  hal::BufferHandle materials() const { return materials_; }
  hal::BufferHandle lights() const { return lights_; }
  hal::BufferHandle bvh_nodes() const { return bvh_nodes_; }
  hal::BufferHandle bvh_triangles() const { return bvh_triangles_; }
  hal::AccelHandle tlas() const { return tlas_; }  // none in the software variant
  // Albedo textures: per-triangle uvs, and the texture table followed by the texels. Untextured
  // scenes get one-element placeholders, and their shaders never read them.
  hal::BufferHandle triangle_uvs() const { return triangle_uvs_; }
  hal::BufferHandle texels() const { return texels_; }
  bool textured() const { return textured_; }
  bool glossy() const { return glossy_; }  // a material has a GGX lobe (metallic or specular > 0)

 private:
  std::vector<GpuTriangle> world_triangles(const scene::FrameState& state) const;
  std::vector<GpuLight> gpu_lights(const scene::FrameState& state, const scene::FrameState& previous,
                                   const std::vector<GpuTriangle>& triangles) const;
  void upload_textures();
  hal::BufferHandle make_buffer(const char* name, std::uint64_t bytes, hal::BufferUsage extra = hal::BufferUsage::None);

  hal::Device& device_;
  const scene::Scene& scene_;
  bool ray_query_;
  bool first_ = true;
  scene::FrameState state_, previous_;
  std::vector<GpuTriangle> current_triangles_;
  std::uint32_t triangle_count_ = 0, light_count_ = 0, sphere_light_count_ = 0;
  Bvh bvh_;
  hal::BufferHandle triangles_, previous_triangles_, materials_, lights_, bvh_nodes_, bvh_triangles_;
  hal::BufferHandle accel_boxes_;
  hal::BufferHandle triangle_uvs_, texels_;
  bool textured_ = false;
  bool glossy_ = false;
  hal::AccelHandle blas_, tlas_;
  std::vector<hal::Resource> owned_;
};

}  // namespace asvgf::render
