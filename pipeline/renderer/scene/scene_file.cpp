// renderer/scene/scene_file.cpp: the JSON scene format. Strict: unknown keys, wrong types and missing
// required keys are errors naming the JSON pointer of the offending value.
#include "renderer/scene/scene_file.hpp"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "renderer/scene/mesh_import.hpp"

namespace asvgf::scene {

namespace {

using nlohmann::json;

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "none" : s;
}

// Appends a key to a JSON pointer, escaping '~' and '/' as RFC 6901 says.
std::string child(const std::string& ptr, const std::string& key) {
  std::string escaped;
  for (char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return ptr + "/" + escaped;
}
std::string child(const std::string& ptr, std::size_t index) {
  return ptr + "/" + std::to_string(index);
}

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& ptr, const std::string& problem) const {
    throw SceneError(file_ + ": " + (ptr.empty() ? "/" : ptr) + ": " + problem);
  }

  // Checks that `j` is an object with only `allowed` keys.
  void object(const json& j, const std::string& ptr, const std::vector<std::string>& allowed) const {
    if (!j.is_object()) fail(ptr, std::string("expected an object, got ") + j.type_name());
    for (const auto& [key, value] : j.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        fail(child(ptr, key), "unknown key '" + key + "' (allowed here: " + join(allowed) + ")");
      }
    }
  }
  const json& required(const json& j, const std::string& ptr, const std::string& key) const {
    if (!j.contains(key)) fail(ptr, "missing required key '" + key + "'");
    return j.at(key);
  }
  const json& array(const json& j, const std::string& ptr) const {
    if (!j.is_array()) fail(ptr, std::string("expected an array, got ") + j.type_name());
    return j;
  }
  std::string string(const json& j, const std::string& ptr) const {
    if (!j.is_string()) fail(ptr, std::string("expected a string, got ") + j.type_name());
    return j.get<std::string>();
  }
  float number(const json& j, const std::string& ptr) const {
    if (!j.is_number()) fail(ptr, std::string("expected a number, got ") + j.type_name());
    const double d = j.get<double>();
    if (!std::isfinite(d) || std::abs(d) > FLT_MAX) fail(ptr, "number " + j.dump() + " is not a finite 32-bit float");
    return static_cast<float>(d);
  }
  std::uint32_t index(const json& j, const std::string& ptr) const {
    if (!j.is_number_unsigned() || j.get<std::uint64_t>() > UINT32_MAX)
      fail(ptr, "expected a non-negative integer, got " + j.dump());
    return j.get<std::uint32_t>();
  }
  template <int N>
  glm::vec<N, float> vec(const json& j, const std::string& ptr) const {
    if (!j.is_array() || j.size() != N ||
        !std::all_of(j.begin(), j.end(), [](const json& e) { return e.is_number(); })) {
      fail(ptr, "expected an array of " + std::to_string(N) + " numbers");
    }
    glm::vec<N, float> v;
    for (int i = 0; i < N; ++i) v[i] = number(j[static_cast<std::size_t>(i)], child(ptr, static_cast<std::size_t>(i)));
    return v;
  }
  glm::vec3 color(const json& j, const std::string& ptr) const {
    const glm::vec3 c = vec<3>(j, ptr);
    if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) fail(ptr, "must not be negative");
    return c;
  }

 private:
  std::string file_;
};

// `line:column` (1-based) of a byte offset, for parse errors.
std::string line_column(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line 3, column 4: ".
std::string parse_problem(const std::string& what) {
  const auto colon = what.find(": ");
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

class Loader {
 public:
  explicit Loader(const std::filesystem::path& path) : path_(path), dir_(path.parent_path()), r_(path.string()) {}

  Scene load() {
    const json root = parse();
    r_.object(root, "", {"name", "frames", "materials", "meshes", "instances", "lights", "camera"});
    scene_.name = root.contains("name") ? r_.string(root["name"], "/name") : path_.stem().string();
    if (root.contains("materials")) {
      const json& mats = r_.array(root["materials"], "/materials");
      for (std::size_t i = 0; i < mats.size(); ++i) material(mats[i], child("/materials", i));
    }
    const json& meshes = r_.array(r_.required(root, "", "meshes"), "/meshes");
    for (std::size_t i = 0; i < meshes.size(); ++i) mesh(meshes[i], child("/meshes", i));
    const json& instances = r_.array(r_.required(root, "", "instances"), "/instances");
    for (std::size_t i = 0; i < instances.size(); ++i) instance(instances[i], child("/instances", i));
    if (root.contains("lights")) {
      const json& lights = r_.array(root["lights"], "/lights");
      for (std::size_t i = 0; i < lights.size(); ++i) light(lights[i], child("/lights", i));
    }
    camera(r_.required(root, "", "camera"), "/camera");
    if (root.contains("frames")) {
      const std::uint32_t n = r_.index(root["frames"], "/frames");
      if (n < 1 || n > 1000000) r_.fail("/frames", "must be in [1, 1000000]");
      scene_.frame_count = static_cast<int>(n);
    } else {
      scene_.frame_count = static_cast<int>(std::ceil(last_keyframe_)) + 1;  // up to the last keyframe
    }
    validate(scene_, r_.file());
    return std::move(scene_);
  }

 private:
  json parse() const {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path_, ec)) throw SceneError(r_.file() + ": no such file");
    std::ifstream in(path_, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw SceneError(r_.file() + ": cannot read file");
    try {
      return json::parse(text.str());
    } catch (const json::parse_error& e) {
      throw SceneError(r_.file() + ":" + line_column(text.str(), e.byte) +
                       ": malformed JSON: " + parse_problem(e.what()));
    } catch (const json::exception& e) {
      throw SceneError(r_.file() + ": malformed JSON: " + parse_problem(e.what()));
    }
  }

  std::uint32_t material_named(const json& j, const std::string& ptr) const {
    const std::string name = r_.string(j, ptr);
    const auto it = material_index_.find(name);
    if (it == material_index_.end()) {
      std::vector<std::string> names;
      for (const auto& [n, i] : material_index_) names.push_back(n);
      r_.fail(ptr, "no material named '" + name + "' (materials: " + join(names) + ")");
    }
    return it->second;
  }

  int texture_file(const std::string& relative, const std::string& ptr) {
    const std::filesystem::path file = dir_ / relative;
    if (auto it = texture_index_.find(file.string()); it != texture_index_.end()) return it->second;
    scene_.textures.push_back(detail::load_image(file, r_.file() + ": " + ptr));
    const int index = static_cast<int>(scene_.textures.size() - 1);
    texture_index_[file.string()] = index;
    return index;
  }

  void material(const json& j, const std::string& ptr) {
    r_.object(j, ptr, {"name", "albedo", "emission", "albedo_texture", "roughness", "metallic", "specular"});
    Material m;
    m.name = r_.string(r_.required(j, ptr, "name"), child(ptr, "name"));
    if (material_index_.count(m.name)) r_.fail(child(ptr, "name"), "duplicate material name '" + m.name + "'");
    if (j.contains("albedo")) {
      m.albedo = r_.color(j["albedo"], child(ptr, "albedo"));
      if (m.albedo.x > 1.0f || m.albedo.y > 1.0f || m.albedo.z > 1.0f)
        r_.fail(child(ptr, "albedo"), "must be in [0, 1]");
    }
    if (j.contains("emission")) m.emission = r_.color(j["emission"], child(ptr, "emission"));
    const std::pair<const char*, float*> surface_params[] = {
        {"roughness", &m.roughness}, {"metallic", &m.metallic}, {"specular", &m.specular}};
    for (const auto& [key, value] : surface_params) {
      if (!j.contains(key)) continue;
      *value = r_.number(j[key], child(ptr, key));
      if (!(*value >= 0.0f && *value <= 1.0f)) r_.fail(child(ptr, key), "must be in [0, 1]");
    }
    if (j.contains("albedo_texture")) {
      const std::string p = child(ptr, "albedo_texture");
      m.albedo_texture = texture_file(r_.string(j["albedo_texture"], p), p);
    }
    material_index_[m.name] = static_cast<std::uint32_t>(scene_.materials.size());
    scene_.materials.push_back(m);
  }

  void mesh(const json& j, const std::string& ptr) {
    r_.object(j, ptr, {"name", "file", "positions", "indices", "uvs", "material"});
    const std::string name = r_.string(r_.required(j, ptr, "name"), child(ptr, "name"));
    if (mesh_index_.count(name)) r_.fail(child(ptr, "name"), "duplicate mesh name '" + name + "'");
    const bool has_override = j.contains("material");
    const std::uint32_t override_material = has_override ? material_named(j["material"], child(ptr, "material")) : 0;
    Mesh m;
    if (j.contains("file") == j.contains("positions")) r_.fail(ptr, "give exactly one of 'file' or 'positions'");
    if (j.contains("file")) {
      const std::string fptr = child(ptr, "file");
      const std::filesystem::path file = dir_ / r_.string(j["file"], fptr);
      std::string ext = file.extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      detail::ImportedMesh im;
      const std::string where = r_.file() + ": " + fptr;
      if (ext == ".obj") {
        im = detail::import_obj(file, where);
      } else if (ext == ".gltf" || ext == ".glb") {
        im = detail::import_gltf(file, where);
      } else {
        r_.fail(fptr, "unsupported mesh file '" + file.filename().string() + "' (expected .obj, .gltf or .glb)");
      }
      if (j.contains("indices") || j.contains("uvs")) r_.fail(ptr, "'indices' and 'uvs' are only for inline meshes");
      m = std::move(im.mesh);
      if (!has_override) {
        // The file's own materials and textures, named "<mesh>/<material>".
        const auto material_base = static_cast<std::uint32_t>(scene_.materials.size());
        const auto texture_base = static_cast<int>(scene_.textures.size());
        for (Material mat : im.materials) {
          mat.name = name + "/" + mat.name;
          if (mat.albedo_texture >= 0) mat.albedo_texture += texture_base;
          scene_.materials.push_back(mat);
        }
        for (Texture& t : im.textures) scene_.textures.push_back(std::move(t));
        for (auto& mi : m.materials) mi += material_base;
      }
    } else {
      if (!has_override) r_.fail(ptr, "missing required key 'material' (inline meshes have no materials of their own)");
      inline_mesh(j, ptr, m);
    }
    m.name = name;
    if (has_override) m.materials.assign(m.triangle_count(), override_material);
    mesh_index_[name] = static_cast<std::uint32_t>(scene_.meshes.size());
    scene_.meshes.push_back(std::move(m));
  }

  void inline_mesh(const json& j, const std::string& ptr, Mesh& m) const {
    const std::string pptr = child(ptr, "positions"), iptr = child(ptr, "indices");
    const json& positions = r_.array(j["positions"], pptr);
    for (std::size_t i = 0; i < positions.size(); ++i) m.positions.push_back(r_.vec<3>(positions[i], child(pptr, i)));
    const json& indices = r_.array(r_.required(j, ptr, "indices"), iptr);
    for (std::size_t t = 0; t < indices.size(); ++t) {
      const std::string tptr = child(iptr, t);
      if (!indices[t].is_array() || indices[t].size() != 3) r_.fail(tptr, "expected an array of 3 vertex indices");
      for (std::size_t c = 0; c < 3; ++c) {
        const std::uint32_t v = r_.index(indices[t][c], child(tptr, c));
        if (v >= m.positions.size()) {
          r_.fail(child(tptr, c), "index " + std::to_string(v) + " out of range (" +
                                      std::to_string(m.positions.size()) + " positions)");
        }
        m.indices.push_back(v);
      }
    }
    if (j.contains("uvs")) {
      const std::string uptr = child(ptr, "uvs");
      const json& uvs = r_.array(j["uvs"], uptr);
      if (uvs.size() != positions.size())
        r_.fail(uptr, "expected one uv per position (" + std::to_string(positions.size()) + ")");
      for (std::size_t i = 0; i < uvs.size(); ++i) m.uvs.push_back(r_.vec<2>(uvs[i], child(uptr, i)));
    }
  }

  void note_frame(float frame) { last_keyframe_ = std::max(last_keyframe_, frame); }

  // Reads keyframes[]: each has "frame" (increasing) and fields `read` fills in on top of the previous
  // keyframe's value (the first starts from `initial`).
  template <typename T, typename Read>
  std::vector<Keyframe<T>> keyframes(const json& j, const std::string& ptr, const T& initial, Read read) {
    const json& keys = r_.array(j, ptr);
    if (keys.empty()) r_.fail(ptr, "expected at least one keyframe");
    std::vector<Keyframe<T>> out;
    T value = initial;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const std::string kptr = child(ptr, k);
      if (!keys[k].is_object()) r_.fail(kptr, std::string("expected an object, got ") + keys[k].type_name());
      const float frame = r_.number(r_.required(keys[k], kptr, "frame"), child(kptr, "frame"));
      if (!out.empty() && !(frame > out.back().frame)) {
        r_.fail(child(kptr, "frame"), "keyframes must have increasing frames (" + std::to_string(frame) + " after " +
                                          std::to_string(out.back().frame) + ")");
      }
      read(keys[k], kptr, value, k == 0);
      out.push_back({frame, value});
      note_frame(frame);
    }
    return out;
  }

  void transform_fields(const json& j, const std::string& ptr, Transform& t, bool with_frame) {
    std::vector<std::string> keys{"translation", "rotation_degrees", "rotation_quat", "scale"};
    if (with_frame) keys.push_back("frame");
    r_.object(j, ptr, keys);
    if (j.contains("translation")) t.translation = r_.vec<3>(j["translation"], child(ptr, "translation"));
    if (j.contains("rotation_degrees") && j.contains("rotation_quat"))
      r_.fail(ptr, "give either 'rotation_degrees' or 'rotation_quat', not both");
    if (j.contains("rotation_degrees")) {
      // Degrees about x, then y, then z (world axes): q = qz * qy * qx.
      const glm::vec3 d = glm::radians(r_.vec<3>(j["rotation_degrees"], child(ptr, "rotation_degrees")));
      t.rotation = glm::angleAxis(d.z, glm::vec3(0, 0, 1)) * glm::angleAxis(d.y, glm::vec3(0, 1, 0)) *
                   glm::angleAxis(d.x, glm::vec3(1, 0, 0));
    }
    if (j.contains("rotation_quat")) {
      const std::string qptr = child(ptr, "rotation_quat");
      const glm::vec4 q = r_.vec<4>(j["rotation_quat"], qptr);
      if (glm::length(q) < 1e-6f) r_.fail(qptr, "quaternion [w, x, y, z] has zero length");
      t.rotation = glm::normalize(glm::quat(q.x, q.y, q.z, q.w));
    }
    if (j.contains("scale")) {
      const std::string sptr = child(ptr, "scale");
      t.scale = j["scale"].is_number() ? glm::vec3(r_.number(j["scale"], sptr)) : r_.vec<3>(j["scale"], sptr);
      if (t.scale.x == 0.0f || t.scale.y == 0.0f || t.scale.z == 0.0f) r_.fail(sptr, "scale must not be zero");
    }
  }

  void instance(const json& j, const std::string& ptr) {
    r_.object(j, ptr, {"name", "mesh", "transform", "keyframes"});
    Instance inst;
    const std::string mptr = child(ptr, "mesh");
    const std::string mesh_name = r_.string(r_.required(j, ptr, "mesh"), mptr);
    const auto it = mesh_index_.find(mesh_name);
    if (it == mesh_index_.end()) {
      std::vector<std::string> names;
      for (const auto& [n, i] : mesh_index_) names.push_back(n);
      r_.fail(mptr, "no mesh named '" + mesh_name + "' (meshes: " + join(names) + ")");
    }
    inst.mesh = it->second;
    inst.name = j.contains("name") ? r_.string(j["name"], child(ptr, "name")) : mesh_name;
    if (j.contains("transform") && j.contains("keyframes"))
      r_.fail(ptr, "give either 'transform' or 'keyframes', not both");
    if (j.contains("keyframes")) {
      inst.transform = keyframes<Transform>(
          j["keyframes"], child(ptr, "keyframes"), Transform{},
          [&](const json& k, const std::string& kptr, Transform& t, bool) { transform_fields(k, kptr, t, true); });
    } else {
      Transform t;
      if (j.contains("transform")) transform_fields(j["transform"], child(ptr, "transform"), t, false);
      inst.transform = {{0.0f, t}};
    }
    scene_.instances.push_back(std::move(inst));
  }

  void light_fields(const json& j, const std::string& ptr, SphereLightState& s, bool first,
                    std::vector<std::string> keys) {
    keys.insert(keys.end(), {"position", "radius", "emission"});
    r_.object(j, ptr, keys);
    if (first) {
      for (const char* k : {"position", "radius", "emission"}) r_.required(j, ptr, k);
    }
    if (j.contains("position")) s.position = r_.vec<3>(j["position"], child(ptr, "position"));
    if (j.contains("radius")) {
      s.radius = r_.number(j["radius"], child(ptr, "radius"));
      if (!(s.radius > 0.0f)) r_.fail(child(ptr, "radius"), "must be > 0");
    }
    if (j.contains("emission")) s.emission = r_.color(j["emission"], child(ptr, "emission"));
  }

  // A sphere light: "position"/"radius"/"emission", or "keyframes" of them.
  void light(const json& j, const std::string& ptr) {
    if (!j.is_object()) r_.fail(ptr, std::string("expected an object, got ") + j.type_name());
    SphereLight l;
    l.name = "light" + std::to_string(scene_.sphere_lights.size());
    if (j.contains("type")) {
      const std::string type = r_.string(j["type"], child(ptr, "type"));
      if (type != "sphere") {
        r_.fail(child(ptr, "type"), "unknown light type '" + type +
                                        "' (only 'sphere'; emissive triangles come from materials with 'emission')");
      }
    }
    if (j.contains("name")) l.name = r_.string(j["name"], child(ptr, "name"));
    if (j.contains("keyframes")) {
      r_.object(j, ptr, {"name", "type", "keyframes"});
      l.state = keyframes<SphereLightState>(j["keyframes"], child(ptr, "keyframes"), SphereLightState{},
                                            [&](const json& k, const std::string& kptr, SphereLightState& s,
                                                bool first) { light_fields(k, kptr, s, first, {"frame"}); });
    } else {
      SphereLightState s;
      light_fields(j, ptr, s, true, {"name", "type", "keyframes"});
      l.state = {{0.0f, s}};
    }
    scene_.sphere_lights.push_back(std::move(l));
  }

  void camera_fields(const json& j, const std::string& ptr, CameraState& c, bool first, bool with_frame) {
    std::vector<std::string> keys{"position", "target", "up", "fov_degrees"};
    if (with_frame) keys.push_back("frame");
    r_.object(j, ptr, keys);
    if (first) {
      r_.required(j, ptr, "position");
      r_.required(j, ptr, "target");
    }
    if (j.contains("position")) c.position = r_.vec<3>(j["position"], child(ptr, "position"));
    if (j.contains("target")) c.target = r_.vec<3>(j["target"], child(ptr, "target"));
    if (j.contains("up")) c.up = r_.vec<3>(j["up"], child(ptr, "up"));
    if (j.contains("fov_degrees")) {
      c.vertical_fov_degrees = r_.number(j["fov_degrees"], child(ptr, "fov_degrees"));
      if (!(c.vertical_fov_degrees > 0.0f && c.vertical_fov_degrees < 180.0f))
        r_.fail(child(ptr, "fov_degrees"), "must be in (0, 180)");
    }
  }

  void camera(const json& j, const std::string& ptr) {
    if (j.is_object() && j.contains("keyframes")) {
      r_.object(j, ptr, {"keyframes"});
      scene_.camera = keyframes<CameraState>(j["keyframes"], child(ptr, "keyframes"), CameraState{},
                                             [&](const json& k, const std::string& kptr, CameraState& c, bool first) {
                                               camera_fields(k, kptr, c, first, true);
                                             });
    } else {
      CameraState c;
      camera_fields(j, ptr, c, true, false);
      scene_.camera = {{0.0f, c}};
    }
  }

  std::filesystem::path path_, dir_;
  Reader r_;
  Scene scene_;
  std::map<std::string, std::uint32_t> material_index_, mesh_index_;
  std::map<std::string, int> texture_index_;
  float last_keyframe_ = 0.0f;
};

}  // namespace

Scene load_scene_file(const std::filesystem::path& json_path) {
  return Loader(json_path).load();
}

}  // namespace asvgf::scene
