// Ray queries: closest hits through a TLAS over several transformed BLASes match a CPU brute-force
// search (same instance custom index and primitive, t within 1e-5 relative), with zero mismatches.
//
// Rays whose answer is numerically ambiguous (grazing a triangle edge within 1e-4 in barycentric
// terms, two hits within 1e-4 relative in t, or a hit within 1e-4 of tmin/tmax) are excluded from
// the comparison: a float traversal may legitimately pick either side. They are counted and must
// stay a small fraction, so the test cannot pass by excluding everything. Float ray origins carry
// about 1e-7 absolute error (GPU traversal transforms them into object space in float), which is
// more than 1e-5 relative of a tiny t: random rays are therefore generated so that what they hit
// is at least 0.1 units away (a rule on generating rays, not an exclusion from the comparison).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "backends.hpp"
#include "data.hpp"
#include "shaders/hal_test_ray_query.rayquery.hpp"

using namespace conformance;
using hal::State;

namespace {

struct Mesh {
  std::string name;
  std::vector<float> vertices;  // xyz
  std::vector<std::uint32_t> indices;
};
struct Instance {
  std::size_t mesh = 0;
  std::array<float, 12> transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  std::uint32_t custom = 0;
};
struct Ray {
  std::array<float, 3> origin;
  float tmin;
  std::array<float, 3> direction;
  float tmax;
};
struct Hit {
  bool hit = false;
  std::uint32_t custom = 0, primitive = 0;
  double t = 0;
  bool ambiguous = false;
};

using Vec = std::array<double, 3>;
Vec sub(Vec a, Vec b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(Vec a, Vec b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(Vec a, Vec b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec apply(const std::array<float, 12>& m, const float* p) {
  Vec out{};
  for (int r = 0; r < 3; ++r) out[r] = double(m[r * 4]) * p[0] + double(m[r * 4 + 1]) * p[1] + double(m[r * 4 + 2]) * p[2] + m[r * 4 + 3];
  return out;
}

// Brute force in double precision over every triangle of every instance, in world space.
Hit closest_hit(const std::vector<Mesh>& meshes, const std::vector<Instance>& instances, const Ray& ray) {
  constexpr double kEdge = 1e-4, kTie = 1e-4;
  const Vec o{ray.origin[0], ray.origin[1], ray.origin[2]}, d{ray.direction[0], ray.direction[1], ray.direction[2]};
  Hit best;
  std::vector<double> ts;
  for (const Instance& inst : instances) {
    const Mesh& mesh = meshes[inst.mesh];
    for (std::uint32_t tri = 0; tri < mesh.indices.size() / 3; ++tri) {
      const Vec v0 = apply(inst.transform, &mesh.vertices[3 * mesh.indices[3 * tri]]);
      const Vec v1 = apply(inst.transform, &mesh.vertices[3 * mesh.indices[3 * tri + 1]]);
      const Vec v2 = apply(inst.transform, &mesh.vertices[3 * mesh.indices[3 * tri + 2]]);
      const Vec e1 = sub(v1, v0), e2 = sub(v2, v0), p = cross(d, e2);
      const double det = dot(e1, p);
      if (std::abs(det) < 1e-14) continue;  // parallel
      const Vec s = sub(o, v0);
      const double u = dot(s, p) / det;
      const Vec q = cross(s, e1);
      const double v = dot(d, q) / det, t = dot(e2, q) / det;
      const double w = 1.0 - u - v;
      const double inside = std::min({u, v, w});
      const bool in_range = t >= ray.tmin && t <= ray.tmax;
      const bool near_range = t >= ray.tmin - kTie * std::max(1.0, std::abs(t)) &&
                              t <= ray.tmax + kTie * std::max(1.0, std::abs(t));
      if (std::abs(inside) < kEdge && near_range) best.ambiguous = true;  // grazes an edge
      if (inside < 0) continue;
      if (!in_range) {
        if (near_range) best.ambiguous = true;  // at tmin/tmax
        continue;
      }
      ts.push_back(t);
      if (!best.hit || t < best.t) {
        best.hit = true;
        best.t = t;
        best.custom = inst.custom;
        best.primitive = tri;
      }
    }
  }
  if (best.hit) {
    int close = 0;
    for (double t : ts)
      if (std::abs(t - best.t) <= kTie * std::max(1e-3, best.t)) ++close;
    if (close > 1) best.ambiguous = true;
  }
  return best;
}

std::array<float, 12> make_transform(std::mt19937& rng, float scale_min, float scale_max, float spread) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  // Rotation from a random unit quaternion, then a non-uniform scale, then a translation.
  float q[4];
  float len = 0;
  do {
    for (float& c : q) c = unit(rng);
    len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  } while (len < 0.1f || len > 1.0f);
  for (float& c : q) c /= len;
  const float x = q[0], y = q[1], z = q[2], w = q[3];
  const float r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
                      2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                      2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
  std::uniform_real_distribution<float> scale(scale_min, scale_max);
  const float s[3] = {scale(rng), scale(rng), scale(rng)};
  std::array<float, 12> m{};
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) m[row * 4 + col] = r[row * 3 + col] * s[col];
    m[row * 4 + 3] = unit(rng) * spread;
  }
  return m;
}

std::array<float, 12> box_transform(float sx, float sy, float sz, float degrees, float tx, float ty, float tz) {
  const float a = degrees * 3.14159265f / 180.0f, c = std::cos(a), s = std::sin(a);
  return {c * sx, 0, s * sz, tx, 0, sy, 0, ty, -s * sx, 0, c * sz, tz};
}

Mesh cube_mesh(const std::string& name) {
  Mesh m{name, {}, {}};
  for (int i = 0; i < 8; ++i)
    for (int axis = 0; axis < 3; ++axis) m.vertices.push_back((i >> axis) & 1 ? 0.5f : -0.5f);
  m.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return m;
}

// Five walls of a 10x10x10 room, open towards +z.
Mesh room_mesh() {
  Mesh m{"room", {}, {}};
  auto quad = [&](std::array<float, 12> corners) {
    const auto base = static_cast<std::uint32_t>(m.vertices.size() / 3);
    m.vertices.insert(m.vertices.end(), corners.begin(), corners.end());
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
  };
  quad({-5, 0, -5, 5, 0, -5, 5, 0, 5, -5, 0, 5});      // floor
  quad({-5, 10, -5, -5, 10, 5, 5, 10, 5, 5, 10, -5});  // ceiling
  quad({-5, 0, -5, -5, 10, -5, 5, 10, -5, 5, 0, -5});  // back
  quad({-5, 0, -5, -5, 0, 5, -5, 10, 5, -5, 10, -5});  // left
  quad({5, 0, -5, 5, 10, -5, 5, 10, 5, 5, 0, 5});      // right
  return m;
}

// The scene on a device: BLAS per mesh, one TLAS, the ray-query pipeline.
class DeviceScene {
 public:
  DeviceScene(hal::Device& device, const std::vector<Mesh>& meshes, std::uint32_t max_instances)
      : device_(device), shader_(asvgf::shaders::hal_test_ray_query_rayquery) {
    const auto usage = hal::BufferUsage::AccelBuildInput | hal::BufferUsage::CopyDst;
    for (const Mesh& mesh : meshes) {
      const auto vb = device.create_buffer({mesh.name + " vertices", mesh.vertices.size() * 4, usage});
      const auto ib = device.create_buffer({mesh.name + " indices", mesh.indices.size() * 4, usage});
      device.upload_buffer(vb, 0, as_bytes(mesh.vertices));
      device.upload_buffer(ib, 0, as_bytes(mesh.indices));
      vertices_.push_back(vb);
      vertex_state_.push_back(State::CopyDst);
      indices_.push_back(ib);
      blases_.push_back(device.create_blas({mesh.name + " blas", vb, static_cast<std::uint32_t>(mesh.vertices.size() / 3),
                                            ib, static_cast<std::uint32_t>(mesh.indices.size() / 3), true}));
    }
    tlas_ = device.create_tlas({"scene tlas", max_instances, true});
    pipeline_ = device.create_pipeline({"ray query", &shader_});
    cmd_ = device.create_command_list("ray query");
  }

  // Builds (or refits) every BLAS and the TLAS over `instances`.
  void build(const std::vector<Instance>& instances, bool update) {
    cmd_->reset();
    cmd_->begin_label(update ? "refit" : "build");
    for (std::size_t m = 0; m < blases_.size(); ++m) {
      if (vertex_state_[m] != State::AccelBuildInput)
        cmd_->barrier({vertices_[m], vertex_state_[m], State::AccelBuildInput});
      vertex_state_[m] = State::AccelBuildInput;
      if (!update) cmd_->barrier({indices_[m], State::CopyDst, State::AccelBuildInput});
      cmd_->barrier({blases_[m], update ? State::AccelRead : State::Undefined, State::AccelWrite});
      cmd_->build_blas(blases_[m], update);
      cmd_->barrier({blases_[m], State::AccelWrite, State::AccelRead});
    }
    std::vector<hal::TlasInstance> list;
    for (const Instance& inst : instances) list.push_back({blases_[inst.mesh], inst.transform, inst.custom, 0xff});
    cmd_->barrier({tlas_, update ? State::AccelRead : State::Undefined, State::AccelWrite});
    cmd_->build_tlas(tlas_, list, update);
    cmd_->barrier({tlas_, State::AccelWrite, State::AccelRead});
    cmd_->end_label();
    device_.submit(*cmd_);
    device_.wait();
  }

  void upload_vertices(std::size_t mesh, const std::vector<float>& vertices) {
    device_.upload_buffer(vertices_[mesh], 0, as_bytes(vertices));
    vertex_state_[mesh] = State::CopyDst;
  }

  std::vector<Hit> trace(const std::vector<Ray>& rays) {
    const auto count = static_cast<std::uint32_t>(rays.size());
    const auto ray_buffer = device_.create_buffer(
        {"rays", rays.size() * sizeof(Ray), hal::BufferUsage::Storage | hal::BufferUsage::CopyDst});
    const auto hit_buffer = device_.create_buffer(
        {"hits", rays.size() * 16, hal::BufferUsage::Storage | hal::BufferUsage::CopySrc});
    device_.upload_buffer(ray_buffer, 0, as_bytes(rays));
    const auto set = device_.create_binding_set(
        {"ray query set", pipeline_, {{"scene", tlas_}, {"rays", ray_buffer}, {"hits", hit_buffer}}});
    cmd_->reset();
    cmd_->barrier({ray_buffer, State::CopyDst, State::ShaderRead});
    cmd_->barrier({hit_buffer, State::Undefined, State::ShaderWrite});
    Uniforms uniforms(shader_);
    uniforms.set("count", count);
    cmd_->dispatch({pipeline_, set, uniforms.bytes(), (count + shader_.workgroup_size[0] - 1) / shader_.workgroup_size[0], 1, 1});
    cmd_->barrier({hit_buffer, State::ShaderWrite, State::CopySrc});
    device_.submit(*cmd_);
    device_.wait();
    std::vector<std::array<std::uint32_t, 4>> raw(rays.size());
    device_.read_buffer(hit_buffer, 0, as_writable(raw));
    device_.destroy(set);
    device_.destroy(ray_buffer);
    device_.destroy(hit_buffer);
    std::vector<Hit> hits(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
      float t;
      std::memcpy(&t, &raw[i][2], 4);
      hits[i] = {raw[i][3] == 1, raw[i][0], raw[i][1], t, false};
    }
    return hits;
  }

 private:
  hal::Device& device_;
  const hal::ShaderInfo& shader_;
  std::vector<hal::BufferHandle> vertices_, indices_;
  std::vector<State> vertex_state_;
  std::vector<hal::AccelHandle> blases_;
  hal::AccelHandle tlas_;
  hal::PipelineHandle pipeline_;
  std::unique_ptr<hal::CommandList> cmd_;
};

// Compares GPU hits with the CPU; returns the number of mismatches among unambiguous rays.
int compare(const std::vector<Mesh>& meshes, const std::vector<Instance>& instances, const std::vector<Ray>& rays,
            const std::vector<Hit>& gpu, const std::string& what) {
  int mismatches = 0, ambiguous = 0, hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Hit cpu = closest_hit(meshes, instances, rays[i]);
    if (cpu.ambiguous) {
      ++ambiguous;
      continue;
    }
    hits += cpu.hit ? 1 : 0;
    const Hit& g = gpu[i];
    bool same = g.hit == cpu.hit;
    if (same && cpu.hit)
      same = g.custom == cpu.custom && g.primitive == cpu.primitive &&
             std::abs(g.t - cpu.t) <= 1e-5 * std::max(cpu.t, 1e-6);
    if (!same && ++mismatches <= 5)
      MESSAGE(what << " ray " << i << ": cpu hit=" << cpu.hit << " custom=" << cpu.custom << " prim=" << cpu.primitive
                   << " t=" << cpu.t << " | gpu hit=" << g.hit << " custom=" << g.custom << " prim=" << g.primitive
                   << " t=" << g.t);
  }
  MESSAGE(what << ": " << rays.size() << " rays, " << hits << " hits, " << ambiguous << " ambiguous (excluded), "
               << mismatches << " mismatches");
  CHECK(ambiguous * 20 < static_cast<int>(rays.size()));  // under 5% excluded
  CHECK(hits * 4 > static_cast<int>(rays.size()));       // the rays mostly hit something
  return mismatches;
}

}  // namespace

TEST_CASE("conformance: ray queries match a CPU brute force on random triangle soups") {
  for_each_backend([](hal::Device& device) {
    if (!device.capabilities().ray_query) {
      MESSAGE("device has no ray queries: skipped");
      return;
    }
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<Mesh> meshes;
    for (int m = 0; m < 3; ++m) {
      Mesh mesh{"soup " + std::to_string(m), {}, {}};
      const int triangles = 24 + 16 * m;
      for (int v = 0; v < triangles * 3 * 3; ++v) mesh.vertices.push_back(unit(rng));
      for (int i = 0; i < triangles * 3; ++i) mesh.indices.push_back(static_cast<std::uint32_t>(i));
      meshes.push_back(std::move(mesh));
    }
    std::vector<Instance> instances;
    for (std::uint32_t i = 0; i < 7; ++i)
      instances.push_back({i % meshes.size(), make_transform(rng, 0.6f, 1.6f, 2.5f), 100 + 37 * i});

    std::vector<Ray> rays;
    std::uniform_real_distribution<float> target(-2.5f, 2.5f);
    for (int r = 0; r < 3000; ++r) {
      // From a sphere of radius 9 towards a random point of the scene's box.
      float dir[3] = {unit(rng), unit(rng), unit(rng)};
      const float len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]) + 1e-6f;
      const std::array<float, 3> origin{9 * dir[0] / len, 9 * dir[1] / len, 9 * dir[2] / len};
      const std::array<float, 3> to{target(rng) - origin[0], target(rng) - origin[1], target(rng) - origin[2]};
      // Some rays start late or end early, so tmin and tmax matter.
      const float tmin = r % 5 == 0 ? 0.3f + 0.5f * (unit(rng) + 1.0f) : 0.0f;
      const float tmax = r % 7 == 0 ? 0.5f + 0.5f * (unit(rng) + 1.0f) : 100.0f;
      rays.push_back({origin, tmin, to, tmax});
    }

    DeviceScene scene(device, meshes, 16);
    scene.build(instances, false);
    CHECK(compare(meshes, instances, rays, scene.trace(rays), "soup build") == 0);

    // Animation: move mesh 0's vertices a little and refit its BLAS, move instances and update
    // the TLAS in place.
    for (float& v : meshes[0].vertices) v += 0.05f * unit(rng);
    scene.upload_vertices(0, meshes[0].vertices);
    for (auto& inst : instances) inst.transform[3] += 0.25f;
    scene.build(instances, true);
    CHECK(compare(meshes, instances, rays, scene.trace(rays), "soup refit") == 0);
  });
}

TEST_CASE("conformance: ray queries match a CPU brute force in a box room") {
  for_each_backend([](hal::Device& device) {
    if (!device.capabilities().ray_query) {
      MESSAGE("device has no ray queries: skipped");
      return;
    }
    const std::vector<Mesh> meshes = {room_mesh(), cube_mesh("box")};
    std::vector<Instance> instances = {{0, box_transform(1, 1, 1, 0, 0, 0, 0), 1},
                                       {1, box_transform(3, 6, 3, 20, -2, 3, -1.5f), 2},
                                       {1, box_transform(3, 3, 3, -15, 2, 1.5f, 1.5f), 3}};
    std::vector<Instance> moved = instances;  // the short box moves later
    moved[2].transform = box_transform(3, 3, 3, 30, 1.0f, 1.5f, -2.5f);
    std::vector<Ray> rays;
    // A 48x48 camera looking into the open side, then random rays from inside the room.
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 48; ++x) {
        const float u = (static_cast<float>(x) + 0.37f) / 48 * 2 - 1, v = (static_cast<float>(y) + 0.61f) / 48 * 2 - 1;
        rays.push_back({{0, 5, 14}, 0.0f, {u * 0.5f, v * 0.5f, -1}, 1000.0f});
      }
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    while (rays.size() < 48 * 48 + 1500) {
      const Ray ray{{4.5f * unit(rng), 5 + 4.5f * unit(rng), 4.5f * unit(rng)}, 0.001f,
                    {unit(rng), unit(rng), unit(rng)}, 1000.0f};
      const Hit before = closest_hit(meshes, instances, ray), after = closest_hit(meshes, moved, ray);
      if ((!before.hit || before.t >= 0.1) && (!after.hit || after.t >= 0.1)) rays.push_back(ray);
    }

    DeviceScene scene(device, meshes, 4);
    scene.build(instances, false);
    CHECK(compare(meshes, instances, rays, scene.trace(rays), "box room") == 0);

    // The short box moves: TLAS update.
    scene.build(moved, true);
    CHECK(compare(meshes, moved, rays, scene.trace(rays), "box room, box moved") == 0);
  });
}
