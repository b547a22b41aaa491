// renderer/scene/gltf_import.cpp: glTF 2.0 (.gltf, .glb) through tinygltf (the shared libtinygltf, so no
// TINYGLTF_IMPLEMENTATION here), merged into one mesh with node transforms applied.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "renderer/scene/mesh_import.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop

namespace asvgf::scene::detail {

namespace {

// tinygltf would decode images with Debian's libstb (stb_image 2.27, unchecked); decode_image
// refuses first what that version mishandles (renderer/scene/image.cpp).
bool decode_gltf_image(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                       const unsigned char* bytes, int size, void*) {
  try {
    Texture tex =
        decode_image(bytes, static_cast<std::size_t>(std::max(size, 0)), "image " + std::to_string(index) + ": ");
    image->width = static_cast<int>(tex.width);
    image->height = static_cast<int>(tex.height);
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(tex.rgba8);
    return true;
  } catch (const SceneError& e) {
    if (err) *err += e.what();
    return false;
  }
}

struct Importer {
  const tinygltf::Model& model;
  std::string prefix;  // "<json>: <place>: <file>: "
  ImportedMesh out;
  std::map<int, std::uint32_t> material_of;  // glTF material (-1: none) -> out.materials
  std::map<int, int> texture_of;             // glTF texture -> out.textures
  std::size_t skipped_primitives = 0;
  bool any_uv = false;

  [[noreturn]] void fail(const std::string& place, const std::string& problem) const {
    throw SceneError(prefix + place + ": " + problem);
  }

  // Element `i`, component `c` of an accessor, as float (normalized integers mapped to [0,1]).
  struct View {
    const unsigned char* data = nullptr;
    std::size_t stride = 0, count = 0;
    int component_type = 0, components = 0;
    bool normalized = false;

    float get(std::size_t i, int c) const {
      const unsigned char* p = data + i * stride;
      switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
          float v;
          std::memcpy(&v, p + 4 * c, 4);
          return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          return normalized ? p[c] / 255.0f : p[c];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          std::uint16_t v;
          std::memcpy(&v, p + 2 * c, 2);
          return normalized ? v / 65535.0f : v;
        }
        default:
          return 0.0f;
      }
    }
    std::uint32_t index(std::size_t i) const {
      const unsigned char* p = data + i * stride;
      if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return p[0];
      if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
      }
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  };

  View view(int accessor_index, const std::string& place) const {
    if (accessor_index < 0 || static_cast<std::size_t>(accessor_index) >= model.accessors.size()) {
      fail(place, "accessor " + std::to_string(accessor_index) + " out of range");
    }
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(accessor_index)];
    const std::string where = place + " (accessor " + std::to_string(accessor_index) + ")";
    if (a.sparse.isSparse) fail(where, "sparse accessors are not supported");
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size()) {
      fail(where, "has no valid bufferView");
    }
    const tinygltf::BufferView& bv = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model.buffers.size())
      fail(where, "bufferView has no valid buffer");
    const tinygltf::Buffer& buffer = model.buffers[static_cast<std::size_t>(bv.buffer)];
    const int stride = a.ByteStride(bv);
    const int component_size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (stride <= 0 || component_size <= 0 || components <= 0) fail(where, "invalid component type or stride");
    View v;
    v.stride = static_cast<std::size_t>(stride);
    v.count = a.count;
    v.component_type = a.componentType;
    v.components = components;
    v.normalized = a.normalized;
    const std::size_t element = static_cast<std::size_t>(component_size) * static_cast<std::size_t>(components);
    const std::size_t begin = bv.byteOffset + a.byteOffset;
    const std::size_t end = a.count == 0 ? begin : begin + (a.count - 1) * v.stride + element;
    if (end > bv.byteOffset + bv.byteLength || end > buffer.data.size()) {
      fail(where, "reads past the end of its buffer (" + std::to_string(end) + " > " +
                      std::to_string(std::min(bv.byteOffset + bv.byteLength, buffer.data.size())) + " bytes)");
    }
    v.data = buffer.data.data() + begin;
    return v;
  }

  int texture(int index, const std::string& place) {
    if (auto it = texture_of.find(index); it != texture_of.end()) return it->second;
    if (index < 0 || static_cast<std::size_t>(index) >= model.textures.size())
      fail(place, "texture index out of range");
    const int source = model.textures[static_cast<std::size_t>(index)].source;
    if (source < 0 || static_cast<std::size_t>(source) >= model.images.size()) fail(place, "texture has no image");
    const tinygltf::Image& img = model.images[static_cast<std::size_t>(source)];
    if (img.width <= 0 || img.height <= 0 || img.component < 1 || img.component > 4 ||
        (img.bits != 8 && img.bits != 16)) {
      fail(place,
           "image " + std::to_string(source) + " ('" + img.name + img.uri + "') is not decoded 8/16-bit image data");
    }
    Texture tex;
    tex.name = img.uri.empty() ? img.name : img.uri;
    tex.width = static_cast<std::uint32_t>(img.width);
    tex.height = static_cast<std::uint32_t>(img.height);
    const std::size_t pixels = std::size_t{tex.width} * tex.height, bytes = static_cast<std::size_t>(img.bits / 8);
    const auto comps = static_cast<std::size_t>(img.component);
    if (img.image.size() < pixels * comps * bytes)
      fail(place, "image " + std::to_string(source) + " has too little data");
    tex.rgba8.resize(pixels * 4);
    for (std::size_t p = 0; p < pixels; ++p) {
      std::uint8_t c[4] = {0, 0, 0, 255};
      // 16-bit: the high byte (little endian). Grey images fill r, g and b.
      for (std::size_t k = 0; k < comps; ++k) c[k] = img.image[(p * comps + k) * bytes + bytes - 1];
      if (comps <= 2) {
        c[3] = comps == 2 ? c[1] : 255;
        c[1] = c[2] = c[0];
      }
      std::memcpy(&tex.rgba8[4 * p], c, 4);
    }
    out.textures.push_back(std::move(tex));
    texture_of[index] = static_cast<int>(out.textures.size() - 1);
    return texture_of[index];
  }

  std::uint32_t material(int index, const std::string& place) {
    if (auto it = material_of.find(index); it != material_of.end()) return it->second;
    Material mat;
    if (index < 0) {
      // Primitives without a material stay our Lambertian default (albedo 0.8), not glTF's default
      // material (a white rough metal), which would turn untextured test geometry into mirrors.
      mat.name = "default";
    } else {
      if (static_cast<std::size_t>(index) >= model.materials.size())
        fail(place, "material " + std::to_string(index) + " out of range");
      const tinygltf::Material& src = model.materials[static_cast<std::size_t>(index)];
      const std::string mplace = "material " + std::to_string(index) + " ('" + src.name + "')";
      mat.name = src.name.empty() ? "material" + std::to_string(index) : src.name;
      const auto& base = src.pbrMetallicRoughness.baseColorFactor;
      if (base.size() >= 3) mat.albedo = {base[0], base[1], base[2]};
      // glTF's model has the GGX lobe always: metallic and roughness default to 1, the dielectric
      // specular factor (KHR_materials_specular) to 1. Their textures are not read (factors only).
      mat.metallic = static_cast<float>(src.pbrMetallicRoughness.metallicFactor);
      mat.roughness = static_cast<float>(src.pbrMetallicRoughness.roughnessFactor);
      mat.specular = 1.0f;
      if (auto ext = src.extensions.find("KHR_materials_specular"); ext != src.extensions.end()) {
        if (ext->second.Has("specularFactor")) {
          mat.specular = static_cast<float>(ext->second.Get("specularFactor").GetNumberAsDouble());
        }
      }
      if (src.emissiveFactor.size() >= 3)
        mat.emission = {src.emissiveFactor[0], src.emissiveFactor[1], src.emissiveFactor[2]};
      if (auto ext = src.extensions.find("KHR_materials_emissive_strength"); ext != src.extensions.end()) {
        if (ext->second.Has("emissiveStrength")) {
          mat.emission *= static_cast<float>(ext->second.Get("emissiveStrength").GetNumberAsDouble());
        }
      }
      if (src.pbrMetallicRoughness.baseColorTexture.index >= 0) {
        mat.albedo_texture = texture(src.pbrMetallicRoughness.baseColorTexture.index, mplace);
      }
    }
    material_of[index] = static_cast<std::uint32_t>(out.materials.size());
    out.materials.push_back(mat);
    return material_of[index];
  }

  void primitive(const tinygltf::Primitive& prim, const glm::mat4& world, const std::string& place) {
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
      ++skipped_primitives;
      return;
    }
    const auto pos = prim.attributes.find("POSITION");
    if (pos == prim.attributes.end()) fail(place, "has no POSITION attribute");
    const View p = view(pos->second, place + " POSITION");
    if (p.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT || p.components != 3)
      fail(place, "POSITION is not float VEC3");
    View uv;
    if (const auto t = prim.attributes.find("TEXCOORD_0"); t != prim.attributes.end()) {
      uv = view(t->second, place + " TEXCOORD_0");
      if (uv.components != 2 || uv.count != p.count) fail(place, "TEXCOORD_0 is not VEC2 with one per position");
      any_uv = true;
    }
    const auto base = static_cast<std::uint32_t>(out.mesh.positions.size());
    for (std::size_t i = 0; i < p.count; ++i) {
      const glm::vec3 local(p.get(i, 0), p.get(i, 1), p.get(i, 2));
      if (!std::isfinite(local.x) || !std::isfinite(local.y) || !std::isfinite(local.z)) {
        fail(place, "vertex " + std::to_string(i) + " is not finite");
      }
      out.mesh.positions.push_back(glm::vec3(world * glm::vec4(local, 1.0f)));
      out.mesh.uvs.push_back(uv.data ? glm::vec2(uv.get(i, 0), uv.get(i, 1)) : glm::vec2(0.0f));
    }
    std::vector<std::uint32_t> idx;
    if (prim.indices >= 0) {
      const View iv = view(prim.indices, place + " indices");
      if (iv.components != 1 || (iv.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                 iv.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                 iv.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
        fail(place, "indices are not unsigned integer scalars");
      }
      for (std::size_t i = 0; i < iv.count; ++i) idx.push_back(iv.index(i));
    } else {
      for (std::size_t i = 0; i < p.count; ++i) idx.push_back(static_cast<std::uint32_t>(i));
    }
    if (idx.size() % 3 != 0) fail(place, std::to_string(idx.size()) + " indices is not a multiple of 3");
    const bool mirrored = glm::determinant(glm::mat3(world)) < 0.0f;  // keep the facing of triangles
    const std::uint32_t mat = material(prim.material, place);
    for (std::size_t t = 0; t < idx.size() / 3; ++t) {
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t i = idx[3 * t + static_cast<std::size_t>(mirrored && c > 0 ? 3 - c : c)];
        if (i >= p.count) {
          fail(place, "triangle " + std::to_string(t) + ": index " + std::to_string(i) + " out of range (" +
                          std::to_string(p.count) + " vertices)");
        }
        out.mesh.indices.push_back(base + i);
      }
      out.mesh.materials.push_back(mat);
    }
  }

  glm::mat4 local_matrix(const tinygltf::Node& node) const {
    if (node.matrix.size() == 16) {
      float m[16];
      for (int i = 0; i < 16; ++i) m[i] = static_cast<float>(node.matrix[static_cast<std::size_t>(i)]);
      return glm::make_mat4(m);  // column-major in both glTF and glm
    }
    glm::mat4 result(1.0f);
    if (node.translation.size() == 3) {
      result = glm::translate(result, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (node.rotation.size() == 4) {  // glTF: x, y, z, w
      result *= glm::mat4_cast(glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                         static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2])));
    }
    if (node.scale.size() == 3) result = glm::scale(result, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    return result;
  }

  void node(int index, const glm::mat4& parent, int depth) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size())
      fail("node " + std::to_string(index), "out of range");
    if (depth > 64) fail("node " + std::to_string(index), "node hierarchy deeper than 64 (a cycle?)");
    const tinygltf::Node& n = model.nodes[static_cast<std::size_t>(index)];
    const glm::mat4 world = parent * local_matrix(n);
    if (n.mesh >= 0) {
      if (static_cast<std::size_t>(n.mesh) >= model.meshes.size())
        fail("node " + std::to_string(index), "mesh index out of range");
      const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(n.mesh)];
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        primitive(mesh.primitives[p], world,
                  "mesh " + std::to_string(n.mesh) + " ('" + mesh.name + "') primitive " + std::to_string(p));
      }
    }
    for (int child : n.children) node(child, world, depth + 1);
  }
};

}  // namespace

ImportedMesh import_gltf(const std::filesystem::path& file, const std::string& where) {
  const std::string prefix = where + ": " + file.string() + ": ";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw SceneError(prefix + "no such file");
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&decode_gltf_image, nullptr);
  std::string err, warn;
  const bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, file.string())
                         : loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw SceneError(prefix + "cannot load glTF: " + (err.empty() ? "unknown error" : err));
  }

  Importer im{model, prefix, {}, {}, {}, 0, false};
  im.out.mesh.name = file.filename().string();
  if (!model.scenes.empty()) {
    const auto s = static_cast<std::size_t>(model.defaultScene >= 0 ? model.defaultScene : 0);
    if (s >= model.scenes.size()) im.fail("scene " + std::to_string(s), "out of range");
    for (int n : model.scenes[s].nodes) im.node(n, glm::mat4(1.0f), 0);
  } else {
    // No scene: every mesh once, untransformed.
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
      for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
        im.primitive(model.meshes[m].primitives[p], glm::mat4(1.0f),
                     "mesh " + std::to_string(m) + " primitive " + std::to_string(p));
      }
    }
  }
  if (im.out.mesh.indices.empty()) {
    throw SceneError(prefix + "no triangles (" + std::to_string(im.skipped_primitives) +
                     " primitives of other modes than TRIANGLES skipped)");
  }
  if (!im.any_uv) im.out.mesh.uvs.clear();  // none of the primitives had texture coordinates
  return std::move(im.out);
}

}  // namespace asvgf::scene::detail
