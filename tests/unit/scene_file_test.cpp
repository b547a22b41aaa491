// Scene files: the examples in tests/data/scenes load with the expected geometry and materials;
// every kind of bad input gives a SceneError naming the file and the place.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>

#include <unistd.h>

#include "renderer/scene/scene_file.hpp"

using namespace asvgf::scene;
namespace fs = std::filesystem;

namespace {

const fs::path kData = fs::path(__FILE__).parent_path().parent_path() / "data" / "scenes";

bool near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
  return glm::length(a - b) <= eps;
}

int material_named(const Scene& s, const std::string& name) {
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    if (s.materials[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::size_t triangles_with(const Mesh& m, int material) {
  std::size_t n = 0;
  for (std::uint32_t mi : m.materials) n += static_cast<int>(mi) == material ? 1 : 0;
  return n;
}

// A scratch folder per test case, holding files written by the case.
struct Scratch {
  fs::path dir;
  Scratch() {
    static int counter = 0;
    dir = fs::temp_directory_path() /
          ("asvgf_scene_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name, std::ios::binary) << text;
    return dir / name;
  }
};

// The error message of loading `file`, or "" when it loads.
std::string error_of(const fs::path& file) {
  try {
    load_scene_file(file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return {};
}

void check_error(const fs::path& file, std::initializer_list<const char*> parts) {
  const std::string what = error_of(file);
  CAPTURE(what);
  REQUIRE_FALSE(what.empty());
  CHECK(what.find(file.filename().string()) != std::string::npos);
  for (const char* p : parts) {
    CAPTURE(p);
    CHECK(what.find(p) != std::string::npos);
  }
}

// A minimal valid scene around one inline mesh / instance / camera; `mesh`, `instance` and `extra`
// replace parts of it.
std::string scene_json(const std::string& mesh = R"({"name": "tri", "material": "white",
      "positions": [[0,0,0],[1,0,0],[0,1,0]], "indices": [[0,1,2]]})",
                       const std::string& instance = R"({"mesh": "tri"})", const std::string& extra = "") {
  return R"({"materials": [{"name": "white", "albedo": [0.5, 0.5, 0.5]}],
  "meshes": [)" +
         mesh + R"(],
  "instances": [)" +
         instance + R"(],
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0]})" +
         extra + "\n}\n";
}

}  // namespace

TEST_CASE("scene file: the OBJ example loads with its triangle counts, MTL and JSON materials, texture and keyframes") {
  const Scene s = load_scene_file(kData / "example_obj.json");
  CHECK(s.name == "example-obj");
  CHECK(s.frame_count == 12);
  REQUIRE(s.meshes.size() == 3);
  const Mesh& box = s.meshes[0];
  const Mesh& red_box = s.meshes[1];
  const Mesh& floor = s.meshes[2];
  CHECK(box.name == "box");
  CHECK(box.triangle_count() == 12);  // six quads, triangulated
  CHECK(red_box.triangle_count() == 12);
  CHECK(floor.triangle_count() == 2);
  CHECK(box.uvs.size() == box.positions.size());
  CHECK(floor.uvs.size() == 4);

  // JSON materials first, then the OBJ's MTL materials named "<mesh>/<material>".
  REQUIRE(s.materials.size() == 4);
  const int white = material_named(s, "box/white"), glow = material_named(s, "box/glow");
  REQUIRE(white >= 0);
  REQUIRE(glow >= 0);
  CHECK(near(s.materials[static_cast<std::size_t>(white)].albedo, glm::vec3(0.7f)));
  CHECK(near(s.materials[static_cast<std::size_t>(glow)].emission, glm::vec3(4.0f)));  // Ke
  CHECK(triangles_with(box, white) == 10);
  CHECK(triangles_with(box, glow) == 2);
  CHECK(triangles_with(red_box, material_named(s, "red")) == 12);  // "material" overrides the MTL
  const Material& floor_mat = s.materials[static_cast<std::size_t>(material_named(s, "floor"))];
  REQUIRE(floor_mat.albedo_texture == 0);
  REQUIRE(s.textures.size() == 1);
  CHECK(s.textures[0].width == 2);
  CHECK(s.textures[0].height == 2);
  CHECK(s.textures[0].rgba8[0] == 255);
  CHECK(s.textures[0].rgba8[4] == 32);
  CHECK(s.textures[0].rgba8[7] == 255);  // alpha added to RGB

  REQUIRE(s.instances.size() == 3);
  CHECK(s.instances[2].name == "sliding_box");
  REQUIRE(s.instances[2].transform.size() == 3);
  // Later keyframes inherit what they leave out: the scale 0.5 of the first.
  CHECK(near(s.instances[2].transform[1].value.scale, glm::vec3(0.5f)));
  const glm::vec4 p = evaluate(s, 8.0f).instance_transforms[2] * glm::vec4(1, 0, 0, 1);
  CHECK(near(glm::vec3(p), {0.8f, 0.25f, 1.0f - 0.5f}, 1e-4f));  // 90 degrees about y, scale 0.5
  const glm::vec4 q = evaluate(s, 0.0f).instance_transforms[1] * glm::vec4(0, 0, 0, 1);
  CHECK(near(glm::vec3(q), {-0.8f, 0.5f, 0.0f}));

  REQUIRE(s.sphere_lights.size() == 1);
  CHECK(s.sphere_lights[0].name == "lamp");
  REQUIRE(s.sphere_lights[0].state.size() == 2);
  CHECK(s.sphere_lights[0].state[1].value.radius == doctest::Approx(0.15f));
  CHECK(near(evaluate(s, 3.0f).lights[0].position, {1.5f, 2.0f, 0.0f}));
  REQUIRE(s.camera.size() == 2);
  CHECK(near(s.camera[1].value.target, {0.0f, 0.5f, 0.0f}));
  CHECK(s.camera[1].value.vertical_fov_degrees == doctest::Approx(45.0f));
}

TEST_CASE("scene file: the glTF example (.gltf and .glb) loads with node transforms, materials, texture and emission") {
  const Scene s = load_scene_file(kData / "example_gltf.json");
  CHECK(s.name == "example-gltf");
  CHECK(s.frame_count == 1);
  REQUIRE(s.meshes.size() == 2);
  for (const std::string mesh : {"quad_text", "quad_binary"}) {
    CAPTURE(mesh);
    const Mesh& m = s.meshes[mesh == "quad_text" ? 0 : 1];
    CHECK(m.triangle_count() == 3);  // textured quad + emissive triangle
    CHECK(m.uvs.size() == m.positions.size());
    const int tile = material_named(s, mesh + "/tile"), glow = material_named(s, mesh + "/glow");
    REQUIRE(tile >= 0);
    REQUIRE(glow >= 0);
    const Material& t = s.materials[static_cast<std::size_t>(tile)];
    CHECK(near(t.albedo, {0.9f, 0.8f, 0.7f}));
    REQUIRE(t.albedo_texture >= 0);
    CHECK(s.textures[static_cast<std::size_t>(t.albedo_texture)].width == 2);
    CHECK(s.textures[static_cast<std::size_t>(t.albedo_texture)].rgba8[4] == 32);
    CHECK(near(s.materials[static_cast<std::size_t>(glow)].emission, {8.0f, 4.0f, 2.0f}));  // factor * strength
    CHECK(triangles_with(m, tile) == 2);
    CHECK(triangles_with(m, glow) == 1);
    // glTF's metallic-roughness model: absent factors are 1 (a rough metal), the dielectric specular 1.
    CHECK(t.metallic == 1.0f);
    CHECK(t.roughness == 1.0f);
    CHECK(t.specular == 1.0f);
    if (mesh == "quad_text") {  // the .glb was written before the factors were added to the .gltf
      CHECK(s.materials[static_cast<std::size_t>(glow)].metallic == 0.25f);
      CHECK(s.materials[static_cast<std::size_t>(glow)].roughness == 0.4f);
    }
    // Quad: node scale 2 under the root's translation (0, 1, 0); lamp: 90 degrees about y.
    for (std::uint32_t i = 0; i < 4; ++i) {
      CHECK(m.positions[i].y == doctest::Approx(1.0f));
      CHECK(std::abs(m.positions[i].x) == doctest::Approx(1.0f));
    }
    CHECK(near(m.positions[5], {0.0f, 1.0f, -1.0f}, 1e-5f));
  }
  CHECK(s.textures.size() == 2);
}

TEST_CASE("scene file: a missing file, malformed JSON or wrong top-level content names the file and the place") {
  Scratch tmp;
  SUBCASE("missing JSON file") {
    check_error(tmp.dir / "absent.json", {"no such file"});
  }
  SUBCASE("malformed JSON gives line:column") {
    check_error(tmp.write("bad.json", "{\n  \"meshes\": [\n    {\"name\": \"a\",, }\n  ]\n}\n"),
                {"bad.json:3:18", "malformed JSON"});
  }
  SUBCASE("number overflow in JSON") {
    check_error(tmp.write("big.json", "{\"frames\": 1e999}"), {"big.json", "malformed JSON", "overflow"});
  }
  SUBCASE("unknown top-level key") {
    check_error(tmp.write("s.json", scene_json().replace(1, 0, "\"light\": [],")),
                {"s.json: /light: unknown key 'light'", "lights"});
  }
  SUBCASE("no camera") {
    check_error(tmp.write("s.json", R"({"meshes": [], "instances": []})"),
                {"s.json: /: missing required key 'camera'"});
  }
  SUBCASE("wrong type of frames") {
    check_error(
        tmp.write(
            "s.json",
            scene_json(
                R"({"name": "tri", "material": "white", "positions": [[0,0,0],[1,0,0],[0,1,0]], "indices": [[0,1,2]]})",
                R"({"mesh": "tri"})", R"(, "frames": "many")")),
        {"/frames", "non-negative integer"});
  }
}

TEST_CASE("scene file: bad instances, keyframes, lights and materials name their JSON pointer") {
  Scratch tmp;
  const std::string tri =
      R"({"name": "tri", "material": "white", "positions": [[0,0,0],[1,0,0],[0,1,0]], "indices": [[0,1,2]]})";
  SUBCASE("translation of the wrong size") {
    check_error(
        tmp.write(
            "s.json",
            scene_json(
                tri,
                R"({"mesh": "tri"}, {"mesh": "tri"}, {"mesh": "tri", "keyframes": [{"frame": 0, "translation": [1, 2]}]})")),
        {"s.json: /instances/2/keyframes/0/translation: expected an array of 3 numbers"});
  }
  SUBCASE("unknown key in a transform") {
    check_error(tmp.write("s.json", scene_json(tri, R"({"mesh": "tri", "transform": {"translate": [0,0,0]}})")),
                {"/instances/0/transform/translate: unknown key 'translate'", "translation"});
  }
  SUBCASE("instance without mesh") {
    check_error(tmp.write("s.json", scene_json(tri, R"({"name": "x"})")),
                {"/instances/0: missing required key 'mesh'"});
  }
  SUBCASE("instance of an unknown mesh") {
    check_error(tmp.write("s.json", scene_json(tri, R"({"mesh": "teapot"})")),
                {"/instances/0/mesh: no mesh named 'teapot'", "tri"});
  }
  SUBCASE("keyframes out of order") {
    check_error(tmp.write("s.json", scene_json(tri, R"({"mesh": "tri", "keyframes": [{"frame": 4}, {"frame": 2}]})")),
                {"/instances/0/keyframes/1/frame", "increasing"});
  }
  SUBCASE("keyframe without frame") {
    check_error(tmp.write("s.json", scene_json(tri, R"({"mesh": "tri", "keyframes": [{"translation": [0,0,0]}]})")),
                {"/instances/0/keyframes/0: missing required key 'frame'"});
  }
  SUBCASE("both rotation forms") {
    check_error(
        tmp.write(
            "s.json",
            scene_json(tri,
                       R"({"mesh": "tri", "transform": {"rotation_degrees": [0,0,0], "rotation_quat": [1,0,0,0]}})")),
        {"/instances/0/transform", "not both"});
  }
  SUBCASE("negative material emission") {
    check_error(
        tmp.write("s.json", R"({"materials": [{"name": "white", "emission": [1, -2, 0]}], "meshes": [], "instances": [],
                                       "camera": {"position": [0,0,1], "target": [0,0,0]}})"),
        {"/materials/0/emission: must not be negative"});
  }
  SUBCASE("albedo above one") {
    check_error(
        tmp.write("s.json", R"({"materials": [{"name": "white", "albedo": [1.5, 0, 0]}], "meshes": [], "instances": [],
                                       "camera": {"position": [0,0,1], "target": [0,0,0]}})"),
        {"/materials/0/albedo"});
  }
  SUBCASE("roughness, metallic or specular outside [0, 1]") {
    for (const char* key : {"roughness", "metallic", "specular"}) {
      CAPTURE(key);
      check_error(tmp.write("s.json", std::string(R"({"materials": [{"name": "white", ")") + key +
                                          R"(": 1.5}], "meshes": [], "instances": [],
        "camera": {"position": [0, 0, 3], "target": [0, 0, 0]}})"),
                  {(std::string("/materials/0/") + key).c_str(), "must be in [0, 1]"});
    }
  }
  SUBCASE("missing albedo texture") {
    check_error(
        tmp.write("s.json",
                  R"({"materials": [{"name": "white", "albedo_texture": "nothere.png"}], "meshes": [], "instances": [],
                                       "camera": {"position": [0,0,1], "target": [0,0,0]}})"),
        {"/materials/0/albedo_texture", "nothere.png", "cannot read image"});
  }
  SUBCASE("sphere radius zero") {
    check_error(
        tmp.write("s.json", scene_json(tri, R"({"mesh": "tri"})",
                                       R"(, "lights": [{"position": [0,1,0], "radius": 0, "emission": [1,1,1]}])")),
        {"/lights/0/radius: must be > 0"});
  }
  SUBCASE("light missing emission") {
    check_error(tmp.write("s.json", scene_json(tri, R"({"mesh": "tri"})",
                                               R"(, "lights": [{"position": [0,1,0], "radius": 0.1}])")),
                {"/lights/0: missing required key 'emission'"});
  }
  SUBCASE("unknown light type") {
    check_error(tmp.write("s.json", scene_json(tri, R"({"mesh": "tri"})", R"(, "lights": [{"type": "area"}])")),
                {"/lights/0/type: unknown light type 'area'"});
  }
  SUBCASE("camera keyframe of the wrong type") {
    check_error(
        tmp.write(
            "s.json",
            R"({"meshes": [], "instances": [], "camera": {"keyframes": [{"frame": 0, "position": [0,0,1], "target": "origin"}]}})"),
        {"/camera/keyframes/0/target: expected an array of 3 numbers"});
  }
}

TEST_CASE("scene file: bad inline meshes name the mesh, triangle and vertex") {
  Scratch tmp;
  SUBCASE("index out of range") {
    check_error(
        tmp.write(
            "s.json",
            scene_json(
                R"({"name": "tri", "material": "white", "positions": [[0,0,0],[1,0,0],[0,1,0]], "indices": [[0,1,2], [0,1,5]]})")),
        {"/meshes/0/indices/1/2: index 5 out of range (3 positions)"});
  }
  SUBCASE("vertex not finite as a float") {
    check_error(
        tmp.write(
            "s.json",
            scene_json(
                R"({"name": "tri", "material": "white", "positions": [[0,0,0],[1e39,0,0],[0,1,0]], "indices": [[0,1,2]]})")),
        {"/meshes/0/positions/1/0", "not a finite"});
  }
  SUBCASE("no triangles at all") {
    check_error(tmp.write("s.json",
                          scene_json(R"({"name": "tri", "material": "white", "positions": [[0,0,0]], "indices": []})")),
                {"no triangles"});
  }
  SUBCASE("unknown material") {
    check_error(
        tmp.write(
            "s.json",
            scene_json(
                R"({"name": "tri", "material": "gold", "positions": [[0,0,0],[1,0,0],[0,1,0]], "indices": [[0,1,2]]})")),
        {"/meshes/0/material: no material named 'gold'", "white"});
  }
  SUBCASE("inline mesh without material") {
    check_error(
        tmp.write("s.json",
                  scene_json(R"({"name": "tri", "positions": [[0,0,0],[1,0,0],[0,1,0]], "indices": [[0,1,2]]})")),
        {"/meshes/0: missing required key 'material'"});
  }
  SUBCASE("both file and positions") {
    check_error(tmp.write("s.json", scene_json(R"({"name": "tri", "file": "a.obj", "positions": []})")),
                {"/meshes/0", "exactly one"});
  }
}

TEST_CASE("scene file: bad OBJ files name the JSON place, the OBJ file and the face or vertex") {
  Scratch tmp;
  const auto with_obj = [&](const std::string& obj_name) {
    return scene_json(R"({"name": "m", "file": ")" + obj_name + R"(", "material": "white"})", R"({"mesh": "m"})");
  };
  SUBCASE("missing mesh file") {
    check_error(tmp.write("s.json", with_obj("nothere.obj")), {"/meshes/0/file", "nothere.obj", "no such file"});
  }
  SUBCASE("unsupported extension") {
    tmp.write("m.ply", "ply\n");
    check_error(tmp.write("s.json", with_obj("m.ply")), {"/meshes/0/file", "m.ply", "unsupported"});
  }
  SUBCASE("face index out of range") {
    tmp.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
    check_error(tmp.write("s.json", with_obj("bad.obj")), {"/meshes/0/file", "bad.obj", "out of bounds", "line 5"});
  }
  SUBCASE("NaN vertex") {
    tmp.write("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
    check_error(tmp.write("s.json", with_obj("nan.obj")), {"nan.obj", "line 2", "vertex 2 is not finite"});
  }
  SUBCASE("no triangles") {
    tmp.write("empty.obj", "v 0 0 0\nv 1 0 0\n");
    check_error(tmp.write("s.json", with_obj("empty.obj")), {"empty.obj", "no triangles"});
  }
  SUBCASE("missing MTL") {
    tmp.write("nomtl.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    check_error(tmp.write("s.json", scene_json(R"({"name": "m", "file": "nomtl.obj"})", R"({"mesh": "m"})")),
                {"nomtl.obj", "gone.mtl"});
  }
}

TEST_CASE("scene file: bad glTF files name the JSON place, the glTF file and the primitive") {
  Scratch tmp;
  const auto with_gltf = [&](const std::string& name) {
    return scene_json(R"({"name": "m", "file": ")" + name + R"("})", R"({"mesh": "m"})");
  };
  // One triangle: 3 float positions, then (for the indexed form) 3 u16 indices 0, 1, 7.
  const auto gltf = [](const std::string& base64, int bytes, bool indexed) {
    return std::string(R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0})") +
           (indexed ? R"(, "indices": 1)" : "") + R"(}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "buffers": [{"byteLength": )" +
           std::to_string(bytes) + R"(, "uri": "data:application/octet-stream;base64,)" + base64 + R"("}]})";
  };
  SUBCASE("index out of range") {
    tmp.write("oob.gltf", gltf("AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAcAAAA=", 44, true));
    check_error(tmp.write("s.json", with_gltf("oob.gltf")),
                {"/meshes/0/file", "oob.gltf", "primitive 0", "triangle 0", "index 7 out of range"});
  }
  SUBCASE("NaN vertex") {
    tmp.write("nan.gltf", gltf("AAAAAAAAAAAAAAAAAADAfwAAAAAAAAAAAAAAAAAAgD8AAAAA", 36, false));
    check_error(tmp.write("s.json", with_gltf("nan.gltf")), {"nan.gltf", "primitive 0", "vertex 1 is not finite"});
  }
  SUBCASE("not glTF") {
    tmp.write("junk.gltf", "{ this is not json");
    check_error(tmp.write("s.json", with_gltf("junk.gltf")), {"/meshes/0/file", "junk.gltf", "cannot load glTF"});
  }
  SUBCASE("missing glb") {
    check_error(tmp.write("s.json", with_gltf("gone.glb")), {"gone.glb", "no such file"});
  }
}

TEST_CASE("scene file: emission beyond 65504 and coordinates beyond 2^30 are errors naming the file and the object") {
  Scratch tmp;
  const std::string tri =
      R"({"name": "tri", "material": "white", "positions": [[0,0,0],[1,0,0],[0,1,0]], "indices": [[0,1,2]]})";
  SUBCASE("material emission above the fp16 histories' range") {
    check_error(tmp.write("s.json", R"({"materials": [{"name": "white"}, {"name": "sun", "emission": [1e5, 1, 1]}],
                                       "meshes": [{"name": "tri", "material": "sun", "positions": [[0,0,0],[1,0,0],[0,1,0]], "indices": [[0,1,2]]}],
                                       "instances": [{"mesh": "tri"}], "camera": {"position": [0,0,1], "target": [0,0,0]}})"),
                {"s.json: material 'sun' (#1): emission (100000, 1, 1)", "65504"});
  }
  SUBCASE("the largest valid emission loads") {
    CHECK(error_of(tmp.write("s.json", R"({"materials": [{"name": "white", "emission": [65504, 65504, 0]}],
                                          "meshes": [)" +
                                           tri + R"(], "instances": [{"mesh": "tri"}],
                                          "camera": {"position": [0,0,1], "target": [0,0,0]}})")) == "");
  }
  SUBCASE("sphere light emission above the range") {
    check_error(
        tmp.write(
            "s.json",
            scene_json(
                tri, R"({"mesh": "tri"})",
                R"(, "lights": [{"name": "bulb", "position": [0,1,0], "radius": 0.1, "emission": [4e11, 4e11, 4e11]}])")),
        {"s.json: sphere light 'bulb' (#0): keyframe 0: emission", "65504"});
  }
  SUBCASE("a vertex beyond 2^30") {
    check_error(
        tmp.write(
            "s.json",
            scene_json(
                R"({"name": "far", "material": "white", "positions": [[0,0,0],[1,0,0],[0,1e10,0]], "indices": [[0,1,2]]})",
                R"({"name": "far_instance", "mesh": "far"})")),
        {"s.json: instance 'far_instance' (#0): keyframe 0: mesh 'far' (#0) vertex 2 lands at (0, 1e+10, 0)", "2^30"});
  }
  SUBCASE("a vertex moved beyond 2^30 by its instance's transform") {
    check_error(
        tmp.write(
            "s.json",
            scene_json(
                tri,
                R"({"name": "moved", "mesh": "tri", "keyframes": [{"frame": 0}, {"frame": 5, "translation": [0, 0, -2e9]}]})")),
        {"instance 'moved' (#0): keyframe 1: mesh 'tri' (#0) vertex 0", "2^30"});
  }
  SUBCASE("a sphere light reaching beyond 2^30") {
    check_error(
        tmp.write("s.json",
                  scene_json(tri, R"({"mesh": "tri"})",
                             R"(, "lights": [{"position": [1073741800,0,0], "radius": 100, "emission": [1,1,1]}])")),
        {"sphere light 'light0' (#0): keyframe 0: the sphere at", "2^30"});
  }
  SUBCASE("a camera beyond 2^30") {
    check_error(tmp.write("s.json", R"({"materials": [{"name": "white"}], "meshes": [)" + tri +
                                        R"(], "instances": [{"mesh": "tri"}],
                                       "camera": {"position": [0,0,3e9], "target": [0,0,0]}})"),
                {"camera: keyframe 0: position (0, 0, 3e+09)", "2^30"});
  }
}
