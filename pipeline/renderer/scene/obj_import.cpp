// renderer/scene/obj_import.cpp: Wavefront OBJ (+ MTL) through tinyobjloader, merged into one mesh.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "renderer/scene/mesh_import.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#include <tiny_obj_loader.h>
#pragma GCC diagnostic pop

namespace asvgf::scene::detail {

namespace {

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

// tinyobjloader reads "nan" and "inf" as 0; find them first, with their line.
void check_vertex_numbers(const std::filesystem::path& file, const std::string& prefix) {
  std::ifstream in(file);
  std::string line;
  std::size_t line_number = 0, vertex = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
    ++vertex;
    std::istringstream fields(line.substr(2));
    std::string token;
    while (fields >> token) {
      const float value = std::strtof(token.c_str(), nullptr);
      if (!std::isfinite(value)) {
        throw SceneError(prefix + "line " + std::to_string(line_number) + ": vertex " + std::to_string(vertex) +
                         " is not finite ('" + token + "')");
      }
    }
  }
}

}  // namespace

ImportedMesh import_obj(const std::filesystem::path& file, const std::string& where) {
  const std::string prefix = where + ": " + file.string() + ": ";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw SceneError(prefix + "no such file");

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = file.parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(file.string(), config))
    throw SceneError(prefix + "cannot parse OBJ: " + trim(reader.Error()));
  // A missing MTL file or an out-of-range face index is only a warning for tinyobjloader; here they
  // would silently drop materials or faces. (A `usemtl` the MTL lacks is common: "default" material.)
  for (const char* fatal : {"not found in a path", "out of bounds"}) {
    if (reader.Warning().find(fatal) != std::string::npos) throw SceneError(prefix + trim(reader.Warning()));
  }
  check_vertex_numbers(file, prefix);

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto vertex_count = attrib.vertices.size() / 3;
  const auto uv_count = attrib.texcoords.size() / 2;
  ImportedMesh out;
  out.mesh.name = file.filename().string();

  // OBJ indexes positions and uvs separately; the scene wants one index per (position, uv) pair.
  std::map<std::pair<int, int>, std::uint32_t> remap;
  bool any_uv = false;
  std::vector<glm::vec2> uvs;
  // OBJ material id (-1: none) -> index in out.materials, filled on first use.
  std::map<int, std::uint32_t> material_of;
  const auto& obj_materials = reader.GetMaterials();

  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& faces = shape.mesh.num_face_vertices;
    std::size_t offset = 0;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      std::ostringstream place;
      place << "shape '" << shape.name << "' face " << f;
      if (faces[f] != 3)
        throw SceneError(prefix + place.str() + ": has " + std::to_string(faces[f]) + " vertices after triangulation");
      for (std::size_t c = 0; c < 3; ++c) {
        const tinyobj::index_t idx = shape.mesh.indices[offset + c];
        if (idx.vertex_index < 0 || static_cast<std::size_t>(idx.vertex_index) >= vertex_count) {
          throw SceneError(prefix + place.str() + ": vertex index " + std::to_string(idx.vertex_index + 1) +
                           " out of range (" + std::to_string(vertex_count) + " vertices)");
        }
        if (idx.texcoord_index >= 0 && static_cast<std::size_t>(idx.texcoord_index) >= uv_count) {
          throw SceneError(prefix + place.str() + ": texture coordinate index " +
                           std::to_string(idx.texcoord_index + 1) + " out of range (" + std::to_string(uv_count) +
                           " texture coordinates)");
        }
        const auto key = std::make_pair(idx.vertex_index, idx.texcoord_index);
        auto it = remap.find(key);
        if (it == remap.end()) {
          const auto v = static_cast<std::size_t>(idx.vertex_index);
          const glm::vec3 p(attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]);
          if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw SceneError(prefix + "vertex " + std::to_string(v + 1) + " is not finite (" + place.str() + ")");
          }
          glm::vec2 uv(0.0f);
          if (idx.texcoord_index >= 0) {
            const auto t = static_cast<std::size_t>(idx.texcoord_index);
            // OBJ's v grows upwards; the scene's (glTF's) downwards from the image's top row.
            uv = {attrib.texcoords[2 * t], 1.0f - attrib.texcoords[2 * t + 1]};
            any_uv = true;
          }
          it = remap.emplace(key, static_cast<std::uint32_t>(out.mesh.positions.size())).first;
          out.mesh.positions.push_back(p);
          uvs.push_back(uv);
        }
        out.mesh.indices.push_back(it->second);
      }
      offset += 3;

      const int mat_id = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
      auto m = material_of.find(mat_id);
      if (m == material_of.end()) {
        Material mat;
        if (mat_id >= 0 && static_cast<std::size_t>(mat_id) < obj_materials.size()) {
          const tinyobj::material_t& src = obj_materials[static_cast<std::size_t>(mat_id)];
          mat.name = src.name;
          mat.albedo = {src.diffuse[0], src.diffuse[1], src.diffuse[2]};
          mat.emission = {src.emission[0], src.emission[1], src.emission[2]};
          if (!src.diffuse_texname.empty()) {
            std::string texname = src.diffuse_texname;  // exporters on Windows write ".\\tex.jpg"
            std::replace(texname.begin(), texname.end(), '\\', '/');
            out.textures.push_back(load_image(file.parent_path() / texname, prefix + "material '" + src.name + "'"));
            mat.albedo_texture = static_cast<int>(out.textures.size() - 1);
          }
        } else {
          mat.name = "default";
        }
        m = material_of.emplace(mat_id, static_cast<std::uint32_t>(out.materials.size())).first;
        out.materials.push_back(mat);
      }
      out.mesh.materials.push_back(m->second);
    }
  }
  if (any_uv) out.mesh.uvs = std::move(uvs);
  if (out.mesh.indices.empty()) throw SceneError(prefix + "no triangles");
  return out;
}

}  // namespace asvgf::scene::detail
