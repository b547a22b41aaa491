// renderer/scene/builtin.hpp: scenes that need no files, each with the same named animations:
//   cornell   the seed's semi-closed room with two boxes and a sphere light (diffuse)
//   glossy    the same room with a rough metal floor (roughness 0.25) and a blue lacquered tall box
//             (dielectric, roughness 0.12) reflecting the light and the short box
//   textured  the same room with a 16x16 checker (4 texels a cell, twice a wall) on the floor and
//             back wall and per-texel white-noise albedo (32 texels a face) on both boxes; side
//             walls and ceiling untextured
//   many      a procedural field of 64 spheres (1520 triangles each, ~98k in all) and 40 boxes on a
//             ground plane under four sphere lights (builtin_many.cpp)
//
// Room: [-1,1]^3, y up; floor y=-1, ceiling y=+1, back wall z=-1, red left wall x=-1, green right
// wall x=+1, open at z=+1 where the camera stands, looking towards -z. Triangles face the inside
// (normal = cross(v1 - v0, v2 - v0)). Instances: 0 "room", 1 "tall_box", 2 "short_box"; one sphere
// light "light" near the ceiling.
//
// Animations of the room scenes (every one has kCornellFrameCount frames; `many`'s are described in
// builtin_many.cpp):
//   static      nothing moves
//   light-exit  the light holds for frames 0..3, then moves 0.4 a frame to the right through the right
//               wall: wholly outside the room (x > 1 + radius) from frame 6 on, stopping at x = 2.4 at
//               frame 9; held there
//   orbit       the camera swings on an arc around the room's centre (+-14 degrees, constant distance),
//               one full back-and-forth period over the animation
//   boxes-move  the short box holds for frames 0..3, slides 0.6 to the left by frame 7 (in front of the
//               tall box), uncovering the floor and back wall behind it; held there
#pragma once

#include <string>
#include <vector>

#include "renderer/scene/scene.hpp"

namespace asvgf::scene {

inline constexpr int kCornellFrameCount = 24;
inline constexpr float kCornellHalfExtent = 1.0f;  // the room spans [-1,1] on every axis
inline constexpr float kCornellLightRadius = 0.12f;
inline constexpr float kCornellLightRadiance = 80.0f;  // per channel, see builtin.cpp

// The unit cube [-0.5,0.5]^3 with outward faces, every triangle `material`; uv_repeat > 0 gives
// each face texture coordinates spanning the texture that many times. Instances scale and place it.
Mesh box_mesh(const std::string& name, std::uint32_t material, float uv_repeat = 0.0f);

std::vector<std::string> builtin_scenes();
std::vector<std::string> builtin_animations();  // animations of every built-in scene

// Throws SceneError listing the valid names when `name` or `animation` is unknown. The scene's
// name is "<name>/<animation>".
Scene builtin_scene(const std::string& name, const std::string& animation = "static");

}  // namespace asvgf::scene
