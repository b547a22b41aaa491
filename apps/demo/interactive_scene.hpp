// demo/interactive_scene.hpp: the scene the Renderer draws, with the user's light and camera.
//
// The Renderer (through SceneGpu) keeps a reference to the scene it was given and evaluates it at
// the frame number on every render(). The demo owns that scene: before each frame it rewrites the
// keyframes so that evaluating at the render frame gives the animation at the demo's own clock
// (which stops while paused) with the user's light and camera in place of the animated ones.
// Nothing else changes (same meshes, instances, materials), so what the GPU holds stays valid.
#pragma once

#include <optional>

#include "renderer/scene/scene.hpp"

namespace asvgf::demo {

class InteractiveScene {
 public:
  explicit InteractiveScene(scene::Scene original);
  InteractiveScene(const InteractiveScene&) = delete;
  InteractiveScene& operator=(const InteractiveScene&) = delete;

  // The scene to give the Renderer (stable address); prepare() rewrites it.
  const scene::Scene& scene() const { return working_; }
  const scene::Scene& original() const { return original_; }

  // Rewrites the working scene for render frame `frame`: the animation at time(), the overrides.
  void prepare(int frame);
  // One frame later on the animation clock, unless paused.
  void advance() {
    if (!paused_) time_ += 1.0f;
  }
  float time() const { return time_; }
  bool paused() const { return paused_; }
  void toggle_pause() { paused_ = !paused_; }
  // The animation from its start, light and camera following it again.
  void restart();

  bool has_light() const { return !original_.sphere_lights.empty(); }
  bool light_overridden() const { return light_.has_value(); }
  bool camera_overridden() const { return camera_.has_value(); }
  // What is shown now (the animation at time(), with the overrides).
  scene::SphereLightState light() const;
  scene::CameraState camera() const;

  // Moves the first sphere light by `delta` (world units); from then on the user holds it.
  void move_light(const glm::vec3& delta);
  // Orbits the camera around its target: yaw about the world up axis, pitch towards it (radians).
  void orbit_camera(float yaw, float pitch);
  // Moves the camera towards its target (factor < 1) or away (> 1).
  void dolly(float factor);

 private:
  scene::Scene original_;
  scene::Scene working_;
  float time_ = 0.0f;
  bool paused_ = false;
  std::optional<scene::SphereLightState> light_;
  std::optional<scene::CameraState> camera_;
};

}  // namespace asvgf::demo
