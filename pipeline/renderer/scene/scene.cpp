// renderer/scene/scene.cpp: keyframe evaluation, state comparison and validation of a CPU scene.
#include "renderer/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

namespace asvgf::scene {

glm::mat4 Transform::matrix() const {
  const glm::mat4 t = glm::translate(glm::mat4(1.0f), translation);
  return t * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

namespace {

// a + (b - a) * t rather than a*(1-t) + b*t: exact when a == b, so a held value between two equal
// keyframes compares equal in same_state().
template <typename V>
V lerp(const V& a, const V& b, float t) {
  return a + (b - a) * t;
}

glm::quat slerp(const glm::quat& a, const glm::quat& b, float t) {
  if (a == b || t <= 0.0f) return a;
  if (t >= 1.0f) return b;
  return glm::normalize(glm::slerp(a, b, t));  // glm::slerp takes the shorter arc
}

Transform interpolate(const Transform& a, const Transform& b, float t) {
  return {lerp(a.translation, b.translation, t), slerp(a.rotation, b.rotation, t), lerp(a.scale, b.scale, t)};
}

SphereLightState interpolate(const SphereLightState& a, const SphereLightState& b, float t) {
  return {lerp(a.position, b.position, t), lerp(a.radius, b.radius, t), lerp(a.emission, b.emission, t)};
}

CameraState interpolate(const CameraState& a, const CameraState& b, float t) {
  return {lerp(a.position, b.position, t), lerp(a.target, b.target, t), lerp(a.up, b.up, t),
          lerp(a.vertical_fov_degrees, b.vertical_fov_degrees, t)};
}

// Keyframes are sorted by frame (validate() checks); hold outside their range.
template <typename T>
T sample(const std::vector<Keyframe<T>>& keys, float frame) {
  if (keys.empty()) return T{};
  if (frame <= keys.front().frame) return keys.front().value;
  if (frame >= keys.back().frame) return keys.back().value;
  const auto next =
      std::upper_bound(keys.begin(), keys.end(), frame, [](float f, const Keyframe<T>& k) { return f < k.frame; });
  const auto prev = next - 1;
  const float span = next->frame - prev->frame;
  if (!(span > 0.0f)) return next->value;
  return interpolate(prev->value, next->value, (frame - prev->frame) / span);
}

bool same(const CameraState& a, const CameraState& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up &&
         a.vertical_fov_degrees == b.vertical_fov_degrees;
}

bool same(const SphereLightState& a, const SphereLightState& b) {
  return a.position == b.position && a.radius == b.radius && a.emission == b.emission;
}

// --- validation helpers ---

template <typename... Args>
[[noreturn]] void fail(const std::string& where, const Args&... parts) {
  std::ostringstream s;
  s << where << ": ";
  (s << ... << parts);
  throw SceneError(s.str());
}

bool finite(float v) {
  return std::isfinite(v);
}
bool finite(const glm::vec3& v) {
  return finite(v.x) && finite(v.y) && finite(v.z);
}
bool finite(const glm::quat& q) {
  return finite(q.w) && finite(q.x) && finite(q.y) && finite(q.z);
}

std::string str(const glm::vec3& v) {
  std::ostringstream s;
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

// "mesh 'box' (#1)": names are optional, indices always present.
std::string label(const char* kind, const std::string& name, std::size_t index) {
  std::ostringstream s;
  s << kind;
  if (!name.empty()) s << " '" << name << "'";
  s << " (#" << index << ")";
  return s.str();
}

bool non_negative(const glm::vec3& v) {
  return finite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f;
}

bool valid_emission(const glm::vec3& v) {
  return non_negative(v) && v.x <= kMaxEmission && v.y <= kMaxEmission && v.z <= kMaxEmission;
}
const char* const kEmissionRange =
    " must be finite, in [0, 65504] per channel (the denoiser's fp16 histories hold no more; scale every "
    "emission down and --exposure up)";

bool in_coordinate_range(const glm::vec3& v) {
  return std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate && std::abs(v.z) <= kMaxCoordinate;
}
const char* const kCoordinateRange =
    " is beyond +-2^30 (1.07e9) on an axis: float32 ray tracing multiplies up to four coordinate differences, "
    "which would overflow";

template <typename T>
void check_keyframes(const std::string& where, const std::string& owner, const std::vector<Keyframe<T>>& keys) {
  if (keys.empty()) fail(where, owner, ": has no keyframe");
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (!finite(keys[k].frame)) fail(where, owner, ": keyframe ", k, " has a non-finite frame number");
    if (k > 0 && !(keys[k].frame > keys[k - 1].frame)) {
      fail(where, owner, ": keyframes are not sorted by frame (keyframe ", k, " at frame ", keys[k].frame,
           " follows frame ", keys[k - 1].frame, ")");
    }
  }
}

void check_mesh(const std::string& where, const Scene& scene, std::size_t m) {
  const Mesh& mesh = scene.meshes[m];
  const std::string who = label("mesh", mesh.name, m);
  if (mesh.indices.size() % 3 != 0) fail(where, who, ": index count ", mesh.indices.size(), " is not a multiple of 3");
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    if (!finite(mesh.positions[v])) fail(where, who, ": vertex ", v, " is not finite ", str(mesh.positions[v]));
  }
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) {
    fail(where, who, ": has ", mesh.uvs.size(), " uvs for ", mesh.positions.size(), " positions");
  }
  for (std::size_t i = 0; i < mesh.uvs.size(); ++i) {
    if (!finite(mesh.uvs[i].x) || !finite(mesh.uvs[i].y)) fail(where, who, ": uv ", i, " is not finite");
  }
  const std::uint32_t triangles = mesh.triangle_count();
  for (std::uint32_t t = 0; t < triangles; ++t) {
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t index = mesh.indices[3 * t + static_cast<std::uint32_t>(c)];
      if (index >= mesh.positions.size()) {
        fail(where, who, ": triangle ", t, ": index ", index, " out of range (", mesh.positions.size(), " vertices)");
      }
    }
  }
  if (mesh.materials.size() != triangles) {
    fail(where, who, ": has ", mesh.materials.size(), " material indices for ", triangles, " triangles");
  }
  for (std::uint32_t t = 0; t < triangles; ++t) {
    if (mesh.materials[t] >= scene.materials.size()) {
      fail(where, who, ": triangle ", t, ": material index ", mesh.materials[t], " out of range (",
           scene.materials.size(), " materials)");
    }
  }
}

}  // namespace

FrameState evaluate(const Scene& scene, float frame) {
  FrameState state;
  state.instance_transforms.reserve(scene.instances.size());
  for (const Instance& instance : scene.instances)
    state.instance_transforms.push_back(sample(instance.transform, frame).matrix());
  state.lights.reserve(scene.sphere_lights.size());
  for (const SphereLight& light : scene.sphere_lights) state.lights.push_back(sample(light.state, frame));
  state.camera = sample(scene.camera, frame);
  return state;
}

bool same_state(const FrameState& a, const FrameState& b) {
  if (!same(a.camera, b.camera)) return false;
  if (a.instance_transforms != b.instance_transforms) return false;
  return std::equal(a.lights.begin(), a.lights.end(), b.lights.begin(), b.lights.end(),
                    [](const SphereLightState& x, const SphereLightState& y) { return same(x, y); });
}

void validate(const Scene& scene, const std::string& where) {
  if (scene.frame_count < 1) fail(where, "frame_count is ", scene.frame_count, ", must be >= 1");

  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    const Texture& tex = scene.textures[t];
    const std::string who = label("texture", tex.name, t);
    if (tex.width == 0 || tex.height == 0) fail(where, who, ": empty size ", tex.width, "x", tex.height);
    if (tex.rgba8.size() != std::size_t{tex.width} * tex.height * 4) {
      fail(where, who, ": ", tex.rgba8.size(), " bytes for ", tex.width, "x", tex.height, " RGBA8 (expected ",
           std::size_t{tex.width} * tex.height * 4, ")");
    }
  }
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const Material& mat = scene.materials[m];
    const std::string who = label("material", mat.name, m);
    if (!non_negative(mat.albedo) || mat.albedo.x > 1.0f || mat.albedo.y > 1.0f || mat.albedo.z > 1.0f) {
      fail(where, who, ": albedo ", str(mat.albedo), " must be finite and in [0, 1]");
    }
    if (!valid_emission(mat.emission)) fail(where, who, ": emission ", str(mat.emission), kEmissionRange);
    const std::pair<const char*, float> unit_params[] = {
        {"roughness", mat.roughness}, {"metallic", mat.metallic}, {"specular", mat.specular}};
    for (const auto& [param, value] : unit_params) {
      if (!(value >= 0.0f && value <= 1.0f)) fail(where, who, ": ", param, " ", value, " must be in [0, 1]");
    }
    if (mat.albedo_texture < -1 || mat.albedo_texture >= static_cast<int>(scene.textures.size())) {
      fail(where, who, ": albedo texture index ", mat.albedo_texture, " out of range (", scene.textures.size(),
           " textures)");
    }
  }
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) check_mesh(where, scene, m);

  std::size_t triangles = 0;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& inst = scene.instances[i];
    const std::string who = label("instance", inst.name, i);
    if (inst.mesh >= scene.meshes.size()) {
      fail(where, who, ": mesh index ", inst.mesh, " out of range (", scene.meshes.size(), " meshes)");
    }
    check_keyframes(where, who, inst.transform);
    for (std::size_t k = 0; k < inst.transform.size(); ++k) {
      const Transform& tr = inst.transform[k].value;
      if (!finite(tr.translation) || !finite(tr.rotation) || !finite(tr.scale)) {
        fail(where, who, ": keyframe ", k, ": transform is not finite");
      }
      if (std::abs(glm::length(tr.rotation) - 1.0f) > 1e-3f)
        fail(where, who, ": keyframe ", k, ": rotation is not a unit quaternion");
      // World space at each keyframe (between keyframes positions are interpolated).
      const glm::mat4 m = tr.matrix();
      const Mesh& mesh = scene.meshes[inst.mesh];
      for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 world(m * glm::vec4(mesh.positions[v], 1.0f));
        if (!in_coordinate_range(world)) {
          fail(where, who, ": keyframe ", k, ": ", label("mesh", mesh.name, inst.mesh), " vertex ", v, " lands at ",
               str(world), ", which", kCoordinateRange);
        }
      }
    }
    triangles += scene.meshes[inst.mesh].triangle_count();
  }
  if (triangles == 0) fail(where, "the scene has no triangles (", scene.instances.size(), " instances)");

  for (std::size_t l = 0; l < scene.sphere_lights.size(); ++l) {
    const SphereLight& light = scene.sphere_lights[l];
    const std::string who = label("sphere light", light.name, l);
    check_keyframes(where, who, light.state);
    for (std::size_t k = 0; k < light.state.size(); ++k) {
      const SphereLightState& s = light.state[k].value;
      if (!finite(s.position)) fail(where, who, ": keyframe ", k, ": position is not finite");
      if (!(s.radius > 0.0f) || !finite(s.radius))
        fail(where, who, ": keyframe ", k, ": radius ", s.radius, " must be > 0");
      if (!in_coordinate_range(glm::abs(s.position) + s.radius))
        fail(where, who, ": keyframe ", k, ": the sphere at ", str(s.position), " of radius ", s.radius,
             kCoordinateRange);
      if (!valid_emission(s.emission))
        fail(where, who, ": keyframe ", k, ": emission ", str(s.emission), kEmissionRange);
    }
  }

  check_keyframes(where, std::string("camera"), scene.camera);
  for (std::size_t k = 0; k < scene.camera.size(); ++k) {
    const CameraState& c = scene.camera[k].value;
    if (!finite(c.position) || !finite(c.target) || !finite(c.up)) fail(where, "camera: keyframe ", k, ": not finite");
    if (!in_coordinate_range(c.position))
      fail(where, "camera: keyframe ", k, ": position ", str(c.position), kCoordinateRange);
    if (!in_coordinate_range(c.target))
      fail(where, "camera: keyframe ", k, ": target ", str(c.target), kCoordinateRange);
    if (glm::length(c.target - c.position) <= 0.0f) fail(where, "camera: keyframe ", k, ": target equals position");
    if (glm::length(glm::cross(c.target - c.position, c.up)) <= 1e-6f * glm::length(c.target - c.position)) {
      fail(where, "camera: keyframe ", k, ": up is zero or parallel to the view direction");
    }
    if (!(c.vertical_fov_degrees > 0.0f && c.vertical_fov_degrees < 180.0f)) {
      fail(where, "camera: keyframe ", k, ": vertical field of view ", c.vertical_fov_degrees,
           " must be in (0, 180) degrees");
    }
  }
}

}  // namespace asvgf::scene
