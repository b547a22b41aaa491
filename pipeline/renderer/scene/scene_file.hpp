// renderer/scene/scene_file.hpp: scenes from a JSON file naming meshes (OBJ, glTF 2.0, or inline arrays),
// materials, sphere lights, camera and keyframed animation. The format is documented in README.md
// ("Scene files"); tests/data/scenes/ holds complete examples.
#pragma once

#include <filesystem>

#include "renderer/scene/scene.hpp"

namespace asvgf::scene {

// Reads, checks and validates a scene file. Throws SceneError naming the file and the place: a JSON
// pointer (`scene.json: /instances/2/keyframes/0/translation: expected an array of 3 numbers`),
// `line:column` for malformed JSON, or the mesh file and the face/vertex/primitive inside it.
Scene load_scene_file(const std::filesystem::path& json_path);

}  // namespace asvgf::scene
