// renderer/scene/scene.hpp: what a scene is on the CPU: meshes, materials, lights, camera and keyframed
// animation, and its evaluated state at a frame. Built-in scenes (builtin.hpp) and scene files
// (scene_file.hpp) both produce this; scene_gpu.hpp uploads it through the HAL.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace asvgf::scene {

// A scene that cannot be built or loaded; the message names the file and the place in it.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Texture {
  std::string name;  // file path or glTF image name, for messages
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba8;  // width*height*4, sRGB-encoded albedo
};

// The valid ranges, checked by validate():
// - Emitted radiance (materials and sphere lights), per channel, in [0, kMaxEmission]: 65504, the
//   largest half float. The denoiser keeps radiance in fp16 histories, so a brighter emitter seen
//   directly could only be clamped; scale every emission down and --exposure up instead (radiance
//   units are relative). Albedo, per channel, in [0, 1] (energy conservation).
// - World-space coordinates (vertices under every instance keyframe, light centres +- radius,
//   camera position and target), per axis, of magnitude <= kMaxCoordinate = 2^30 (~1.07e9). Ray
//   tracing in float32 multiplies up to four coordinate differences (|cross(e1, e2)|^2 when a
//   sample is projected forward; the watertight test's depth is a product of three), and
//   (2 * 2^30)^4 = 2^124 stays below float32's largest value 2^128. Scenes are scale-independent
//   below it: the ray offsets are relative (shaders/renderer/pathtrace.comp).
constexpr float kMaxEmission = 65504.0f;
constexpr float kMaxCoordinate = 1073741824.0f;  // 2^30

// Lambertian by default. metallic or specular above 0 adds glTF's GGX lobe (metallic-roughness
// model, shaders/common/bsdf.glsl): albedo is then the base colour, a metal's Fresnel colour where
// metallic = 1. All three in [0, 1].
struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};    // diffuse reflectance (base colour) in [0,1]
  glm::vec3 emission{0.0f};  // emitted radiance (W/(sr m^2)) in [0, kMaxEmission]; > 0 makes every triangle a light
  int albedo_texture = -1;   // index into Scene::textures, multiplies albedo; -1: none
  float roughness = 1.0f;    // perceptual roughness (GGX alpha = roughness^2, at least 0.002)
  float metallic = 0.0f;     // 0 dielectric, 1 metal
  float specular = 0.0f;     // dielectric reflectance factor: 0.04 * specular at normal incidence (glTF: 1)
  bool glossy() const { return metallic > 0.0f || specular > 0.0f; }
};

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> uvs;            // empty, or one per position; v = 0 is the texture's top row
  std::vector<std::uint32_t> indices;    // three per triangle
  std::vector<std::uint32_t> materials;  // one material index per triangle
  std::uint32_t triangle_count() const { return static_cast<std::uint32_t>(indices.size() / 3); }
};

struct Transform {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
  glm::mat4 matrix() const;  // translation * rotation * scale
};

// Keyframes on frame numbers; values between keyframes are interpolated linearly (rotation:
// slerp), before the first and after the last they hold.
template <typename T>
struct Keyframe {
  float frame = 0;
  T value{};
};

struct Instance {
  std::string name;
  std::uint32_t mesh = 0;
  std::vector<Keyframe<Transform>> transform;  // at least one
};

struct SphereLightState {
  glm::vec3 position{0.0f};
  float radius = 0.1f;
  glm::vec3 emission{1.0f};  // radiance of the sphere's surface
};
struct SphereLight {
  std::string name;
  std::vector<Keyframe<SphereLightState>> state;  // at least one
};

struct CameraState {
  glm::vec3 position{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float vertical_fov_degrees = 45.0f;
};

struct Scene {
  std::string name;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Instance> instances;
  std::vector<SphereLight> sphere_lights;
  std::vector<Keyframe<CameraState>> camera;  // at least one
  int frame_count = 1;                        // length of the animation, in frames (>= 1)
};

// Everything that moves, evaluated at one frame.
struct FrameState {
  std::vector<glm::mat4> instance_transforms;  // object -> world, one per instance
  std::vector<SphereLightState> lights;
  CameraState camera;
};
FrameState evaluate(const Scene& scene, float frame);

// True when nothing (camera, any instance, any light) differs between two evaluated frames.
bool same_state(const FrameState& a, const FrameState& b);

// Checks a scene for what would break rendering (no triangles, NaN vertex, index or material out of
// range, bad texture, values outside the valid ranges above): throws SceneError naming `where`, the
// object (material, mesh and vertex, instance and keyframe, light, camera) and the problem.
void validate(const Scene& scene, const std::string& where);

}  // namespace asvgf::scene
