#include "interactive_scene.hpp"

#include <algorithm>
#include <cmath>

namespace asvgf::demo {
namespace {

// Keyframes moved in time by `offset` frames: evaluating them at t + offset gives what the
// originals give at t (interpolation only looks at differences between keyframe times).
template <typename T>
std::vector<scene::Keyframe<T>> shifted(const std::vector<scene::Keyframe<T>>& keys, float offset) {
  std::vector<scene::Keyframe<T>> out = keys;
  for (auto& k : out) k.frame += offset;
  return out;
}

constexpr float kMaxPitch = 1.48f;  // ~85 degrees: the view never flips over the pole

}  // namespace

InteractiveScene::InteractiveScene(scene::Scene original) : original_(std::move(original)), working_(original_) {}

void InteractiveScene::restart() {
  time_ = 0.0f;
  light_.reset();
  camera_.reset();
}

scene::SphereLightState InteractiveScene::light() const {
  if (light_) return *light_;
  const auto state = scene::evaluate(original_, time_);
  return state.lights.empty() ? scene::SphereLightState{} : state.lights.front();
}

scene::CameraState InteractiveScene::camera() const {
  return camera_ ? *camera_ : scene::evaluate(original_, time_).camera;
}

void InteractiveScene::prepare(int frame) {
  // The render frame only grows (the Renderer treats a step back as a cut); the clock may stand.
  const float offset = static_cast<float>(frame) - time_;
  for (std::size_t i = 0; i < original_.instances.size(); ++i)
    working_.instances[i].transform = shifted(original_.instances[i].transform, offset);
  for (std::size_t i = 0; i < original_.sphere_lights.size(); ++i)
    working_.sphere_lights[i].state = shifted(original_.sphere_lights[i].state, offset);
  if (light_ && !working_.sphere_lights.empty()) working_.sphere_lights.front().state = {{0.0f, *light_}};
  working_.camera = camera_ ? std::vector<scene::Keyframe<scene::CameraState>>{{0.0f, *camera_}}
                            : shifted(original_.camera, offset);
}

void InteractiveScene::move_light(const glm::vec3& delta) {
  if (!has_light()) return;
  scene::SphereLightState l = light();
  l.position += delta;
  light_ = l;
}

void InteractiveScene::orbit_camera(float yaw, float pitch) {
  scene::CameraState c = camera();
  const glm::vec3 offset = c.position - c.target;
  const float distance = glm::length(offset);
  if (distance <= 0.0f) return;
  const glm::vec3 up = glm::normalize(c.up);
  // Spherical angles of the offset about `up`, measured in a frame built from the current view.
  const float current_pitch = std::asin(std::clamp(glm::dot(offset / distance, up), -1.0f, 1.0f));
  glm::vec3 flat = offset - up * glm::dot(offset, up);
  if (glm::length(flat) < 1e-6f) flat = glm::vec3(0, 0, 1);
  flat = glm::normalize(flat);
  const glm::vec3 side = glm::cross(up, flat);
  const float new_pitch = std::clamp(current_pitch + pitch, -kMaxPitch, kMaxPitch);
  const glm::vec3 new_flat = flat * std::cos(yaw) + side * std::sin(yaw);
  c.position = c.target + distance * (new_flat * std::cos(new_pitch) + up * std::sin(new_pitch));
  camera_ = c;
}

void InteractiveScene::dolly(float factor) {
  scene::CameraState c = camera();
  const glm::vec3 offset = c.position - c.target;
  const float distance = std::clamp(glm::length(offset) * factor, 0.2f, 100.0f);
  if (glm::length(offset) <= 0.0f) return;
  c.position = c.target + glm::normalize(offset) * distance;
  camera_ = c;
}

}  // namespace asvgf::demo
