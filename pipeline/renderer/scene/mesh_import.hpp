// renderer/scene/mesh_import.hpp: reading mesh and image files for scene_file.cpp (internal to the scene
// layer). Every error is a SceneError starting with `where` (the JSON file and place that named the
// file) followed by the mesh or image file and the place inside it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/scene/scene.hpp"

namespace asvgf::scene::detail {

// A file's geometry merged into one mesh (glTF node transforms applied), with the materials and
// textures it brings. Mesh::materials index `materials`; Material::albedo_texture indexes `textures`.
struct ImportedMesh {
  Mesh mesh;
  std::vector<Material> materials;
  std::vector<Texture> textures;
};

// Wavefront OBJ (triangulated); materials from its MTL (Kd: albedo, Ke: emission, map_Kd: albedo
// texture); faces without a material get one named "default".
ImportedMesh import_obj(const std::filesystem::path& file, const std::string& where);

// glTF 2.0 (.gltf or .glb): triangle primitives of the default scene's nodes, baseColorFactor/
// baseColorTexture as albedo, emissiveFactor (times KHR_materials_emissive_strength) as emission.
ImportedMesh import_gltf(const std::filesystem::path& file, const std::string& where);

// PNG/JPG/... through stb_image, as RGBA8.
Texture load_image(const std::filesystem::path& file, const std::string& where);
// The same from bytes in memory (glTF's embedded and referenced images); errors start with `prefix`.
// The returned texture has no name.
Texture decode_image(const unsigned char* data, std::size_t size, const std::string& prefix);

}  // namespace asvgf::scene::detail
