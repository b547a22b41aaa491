// renderer/scene/builtin_many.hpp: the built-in `many` scene (builtin_many.cpp), for tracing and BVH scale.
#pragma once

#include <string>

#include "renderer/scene/scene.hpp"

namespace asvgf::scene {

inline constexpr int kManySpheres = 64;
inline constexpr int kManyBoxes = 40;
inline constexpr int kManyLights = 4;

// Throws SceneError listing the valid animations when `animation` is unknown.
Scene many_scene(const std::string& animation);

}  // namespace asvgf::scene
