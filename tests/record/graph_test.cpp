// The render graph on the recording HAL: barriers derived from declarations, culling, aliasing,
// history ping-pong, compile errors, and the real A-SVGF frame of every method.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "asvgf/graph_runtime.hpp"
#include "asvgf/pass_traffic.hpp"
#include "checked_record.hpp"
#include "hal/error.hpp"
#include "hal_record/record_device.hpp"
#include "renderer/frame_graph.hpp"
#include "renderer/scene/builtin.hpp"

using namespace asvgf;
using graph::GraphBarrier;
using graph::Lifetime;
using graph::Use;
using hal::State;

namespace {
std::string messages(const hal::record::RecordDevice& d) {
  std::string s;
  for (const auto& r : d.reports()) s += r.message + "\n";
  return s;
}

// The built-in room on the recording HAL, with output images, run frame after frame.
struct Scene : CheckedRecord {
  explicit Scene(hal::record::RecordOptions options = {}) : CheckedRecord(options) {}
  scene::Scene room = scene::builtin_scene("cornell", "light-exit");
  render::SceneGpu gpu{device, room, true};
  hal::ImageHandle hdr, display;
  hal::BufferHandle rays;
  hal::State hdr_state = State::Undefined, display_state = State::Undefined;
  std::uint32_t width = 0, height = 0;

  frame::FrameTargets targets(std::uint32_t w, std::uint32_t h) {
    if (w != width || h != height) {
      const auto usage = hal::ImageUsage::Storage | hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc;
      hdr = device.create_image({"hdr", w, h, hal::Format::RGBA32F, usage});
      display = device.create_image({"display", w, h, hal::Format::RGBA8Unorm, usage});
      hdr_state = display_state = State::Undefined;
      width = w;
      height = h;
    }
    if (!rays) rays = device.create_buffer({"ray_counter", 16, hal::BufferUsage::Storage | hal::BufferUsage::CopyDst});
    std::array<std::byte, 16> zeros{};
    device.upload_buffer(rays, 0, zeros);
    return {hdr, hdr_state, hal::Format::RGBA32F, display, display_state, {}, State::Undefined, rays, State::CopyDst};
  }
  void frame_done() { hdr_state = display_state = State::CopySrc; }
};

// Runs `frames` frames of a method; `mutate` may edit each frame's graph before compiling.
// Starts at `first` (light-exit moves from frame 4 on).
void run_frames(Scene& scene, frame::FrameSettings settings, int frames,
                const std::function<void(graph::RenderGraph&)>& mutate = {}, int first = 0, bool binding_checks = true,
                std::vector<std::string>* culled = nullptr) {
  graph::GraphRuntime runtime(scene.device);
  runtime.set_binding_checks(binding_checks);
  frame::FrameGraphBuilder builder(scene.device);
  auto cmd = scene.device.create_command_list("frame");
  for (int f = 0; f < frames; ++f) {
    settings.scene_moved = scene.gpu.update(static_cast<float>(first + f)) && f > 0;
    settings.frame = static_cast<std::uint32_t>(first + f);
    auto g = builder.build(settings, scene.gpu, scene.targets(settings.width, settings.height));
    if (mutate) mutate(g);
    auto compiled = runtime.compile(g);
    if (culled) {
      culled->clear();
      for (const auto& c : compiled.culled) culled->push_back(c.name);
    }
    runtime.execute(compiled, *cmd);
    scene.device.submit(*cmd);
    scene.device.wait();
    cmd->reset();
    scene.frame_done();
  }
}

}  // namespace

TEST_CASE("every method's frame compiles and runs 4 frames on the recording HAL with no report") {
  for (frame::Method method : frame::kAllMethods) {
    CAPTURE(frame::to_string(method));
    Scene scene;
    frame::FrameSettings s;
    s.method = method;
    s.width = 20;
    s.height = 14;
    run_frames(scene, s, 4, {}, 3);  // frames 3..6: still, then moving
    CHECK_MESSAGE(scene.record.reports().empty(), messages(scene.record));
    // Frames alternate between moving and still scenes: gradient passes come and go.
    Scene scene2;
    graph::GraphRuntime runtime(scene2.device);
    frame::FrameGraphBuilder builder(scene2.device);
    auto cmd = scene2.device.create_command_list("frame");
    for (int f = 0; f < 4; ++f) {
      scene2.gpu.update(static_cast<float>(f));
      s.scene_moved = f % 2 == 0;
      s.frame = static_cast<std::uint32_t>(f);
      auto g = builder.build(s, scene2.gpu, scene2.targets(s.width, s.height));
      runtime.execute(runtime.compile(g), *cmd);
      scene2.device.submit(*cmd);
      scene2.device.wait();
      cmd->reset();
      scene2.frame_done();
    }
    CHECK_MESSAGE(scene2.record.reports().empty(), messages(scene2.record));
  }
}

// Runs the light-exit frames 4..6 (the light moves: every asvgf pass runs) with one declared
// access of one pass deleted, and says who caught it.
// Culled: the pass wrote nothing else, so the graph left it out (dump() lists it with the reason).
// Validation: the HAL validation layer refused a command (a binding left unbound).
enum class Caught { Compile, Execute, RecordingHal, Culled, Validation, Nothing };
Caught delete_one_access(const frame::FrameSettings& s, const std::string& pass, const graph::PassAccess& access,
                         bool binding_checks) {
  Scene scene;
  std::vector<std::string> culled;
  try {
    run_frames(
        scene, s, 3,
        [&](graph::RenderGraph& g) {
          for (auto& p : g.passes()) {
            if (p.name != pass) continue;
            for (auto it = p.accesses.begin(); it != p.accesses.end(); ++it)
              if (it->resource == access.resource && it->use == access.use && it->history == access.history) {
                p.accesses.erase(it);
                break;
              }
          }
        },
        4, binding_checks, &culled);
  } catch (const graph::GraphError& e) {
    return std::string(e.what()).find("does not declare") != std::string::npos ? Caught::Execute : Caught::Compile;
  } catch (const hal::Error&) {
    return Caught::Validation;
  }
  if (!scene.record.reports().empty()) return Caught::RecordingHal;
  return std::find(culled.begin(), culled.end(), pass) != culled.end() ? Caught::Culled : Caught::Nothing;
}

struct Mutation {
  std::string pass;
  graph::PassAccess access;
  std::string resource;
};
std::vector<Mutation> asvgf_mutations(frame::FrameSettings s) {
  Scene probe;
  probe.gpu.update(4);
  probe.gpu.update(5);
  frame::FrameGraphBuilder builder(probe.device);
  s.scene_moved = true;
  const auto g = builder.build(s, probe.gpu, probe.targets(s.width, s.height));
  std::vector<Mutation> out;
  for (const auto& p : g.passes())
    if (p.name != "debug_view")  // culled: its declarations record nothing
      for (const auto& a : p.accesses) out.push_back({p.name, a, g.resource(a.resource).name});
  return out;
}

frame::FrameSettings small_asvgf() {
  frame::FrameSettings s;
  s.width = 12;
  s.height = 9;
  s.denoise.atrous_iterations = 2;
  s.denoise.gradient_iterations = 2;
  return s;
}

TEST_CASE("deleting any one declared access of an asvgf pass is caught by the graph or the recording HAL") {
  const auto s = small_asvgf();
  int by[6] = {0, 0, 0, 0, 0, 0};
  for (const auto& m : asvgf_mutations(s)) {
    CAPTURE(m.pass);
    CAPTURE(m.resource);
    CAPTURE(m.access.history);
    const Caught c = delete_one_access(s, m.pass, m.access, true);
    CHECK(c != Caught::Nothing);
    ++by[static_cast<int>(c)];
  }
  MESSAGE(by[0] << " refused at compile, " << by[1] << " at execute (bound but undeclared), " << by[2]
                << " reported by the recording HAL, " << by[3] << " culled the pass (its only write deleted), " << by[4]
                << " refused by the HAL validation layer");
}

TEST_CASE("without the graph's binding check, the recording HAL catches every deleted write on its own") {
  // A deleted read can leave the program correct (another pass's read of the same version already
  // placed the barrier) or wrong only through aliasing (the slot's data changes, in order); those
  // need the graph's own check above. Every deleted write must give a hazard or a compile error.
  const auto s = small_asvgf();
  int hal_reports = 0, silent_reads = 0;
  for (const auto& m : asvgf_mutations(s)) {
    CAPTURE(m.pass);
    CAPTURE(m.resource);
    CAPTURE(m.access.history);
    const Caught c = delete_one_access(s, m.pass, m.access, false);
    if (graph::writes(m.access.use)) CHECK(c != Caught::Nothing);
    if (c == Caught::RecordingHal) ++hal_reports;
    if (c == Caught::Nothing) ++silent_reads;
  }
  MESSAGE(hal_reports << " deletions reported by the recording HAL, " << silent_reads << " reads not caught by it");
  CHECK(hal_reports > 10);
}

TEST_CASE(
    "the a-trous chain passes packed filter texels in storage buffers where the device's storage binding holds them, "
    "RGBA16F images otherwise and for the box kernel") {
  // "name:buffer" / "name:image" for each a-trous resource of one frame, which must also run clean.
  const auto kinds = [](std::uint64_t max_storage_buffer_range, asvgf::AtrousKernel kernel) {
    hal::record::RecordOptions options;
    options.capabilities.max_storage_buffer_range = max_storage_buffer_range;
    Scene scene(options);
    graph::GraphRuntime runtime(scene.device);
    frame::FrameGraphBuilder builder(scene.device);
    frame::FrameSettings s;
    s.width = 32;
    s.height = 16;
    s.denoise.kernel = kernel;
    scene.gpu.update(0);
    auto g = builder.build(s, scene.gpu, scene.targets(32, 16));
    std::string out;
    for (const auto& r : g.resources())
      if (r.name.rfind("atrous.", 0) == 0)
        out += r.name + (r.kind == hal::ResourceKind::Buffer ? ":buffer " : ":image ");
    auto cmd = scene.device.create_command_list("frame");
    runtime.execute(runtime.compile(g), *cmd);
    scene.device.submit(*cmd);
    scene.device.wait();
    CHECK(messages(scene.record).empty());
    return out;
  };
  const std::uint64_t packed_bytes = 32 * 16 * 8;
  // (atrous.5.rgb9e5: the last iteration's colour for the composite's local-mean correction.)
  CHECK(kinds(packed_bytes, asvgf::AtrousKernel::B3Spline) ==
        "atrous.1:buffer atrous.2:buffer atrous.3:buffer atrous.4:buffer atrous.5:image atrous.5.rgb9e5:image ");
  CHECK(kinds(packed_bytes - 1, asvgf::AtrousKernel::B3Spline) ==
        "atrous.1:image atrous.2:image atrous.3:image atrous.4:image atrous.5:image ");
  CHECK(kinds(packed_bytes, asvgf::AtrousKernel::Box) ==
        "atrous.1:image atrous.2:image atrous.3:image atrous.4:image atrous.5:image ");
}

TEST_CASE(
    "culling: an output nobody reads culls its pass, a still frame culls the gradient passes, the composite "
    "applies the local-mean correction itself") {
  Scene scene;
  graph::GraphRuntime runtime(scene.device);
  frame::FrameGraphBuilder builder(scene.device);
  frame::FrameSettings s;
  s.width = 16;
  s.height = 16;
  s.scene_moved = false;
  {
    // The default (the local-mean correction on): the corrected colour's own pass writes what only a
    // reader of the denoiser's outputs wants; the last iteration's RGB9E5 output is read by the
    // composite's correction, and its RGBA16F twin by nothing.
    scene.gpu.update(0);
    auto compiled = runtime.compile(builder.build(s, scene.gpu, scene.targets(16, 16)));
    std::map<std::string, std::string> culled;
    for (const auto& c : compiled.culled) culled[c.name] = c.reason;
    for (const char* name : {"variance", "local_mean", "atrous.5.rgba16f"}) {
      CAPTURE(name);
      REQUIRE(culled.count(name) == 1);
      CHECK(culled[name].find("nothing that contributes") != std::string::npos);
    }
    CHECK(culled.count("atrous.5") == 0);
    CHECK(culled.count("local_mean.blocks") == 0);
  }
  // Without it, the paper's filter: the last a-trous iteration composites.
  s.denoise.local_mean = 0;
  scene.gpu.update(0);
  auto g = builder.build(s, scene.gpu, scene.targets(16, 16));
  auto compiled = runtime.compile(g);
  std::map<std::string, std::string> culled;
  for (const auto& c : compiled.culled) culled[c.name] = c.reason;
  CHECK(culled.count("debug_view") == 1);
  CHECK(culled["debug_view"].find("nothing that contributes") != std::string::npos);
  // (No "gradient" pass: with the renderer's l_cur the first gradient a-trous iteration computes it.)
  CHECK(culled.count("gradient") == 0);
  for (const char* name :
       {"gradient_clear", "gradient_select", "gradient_resolve", "gradient_atrous.1", "gradient_atrous.3"}) {
    CAPTURE(name);
    REQUIRE(culled.count(name) == 1);
    CHECK(culled[name].find("nothing in the scene, camera or lights moved") != std::string::npos);
  }
  const std::string text = compiled.text();
  CHECK(text.find("left out:") != std::string::npos);
  CHECK(text.find("debug_view: nothing that contributes") != std::string::npos);
  CHECK(text.find("gradient_select: nothing in the scene") != std::string::npos);
  CHECK(compiled.dot().find("left out") != std::string::npos);
  // The variance pass and the last a-trous iteration's plain twin write what only a reader of the
  // denoiser's outputs wants (the first iteration estimates the variance, the last composites).
  for (const char* name : {"variance", "atrous.5"}) {
    CAPTURE(name);
    REQUIRE(culled.count(name) == 1);
    CHECK(culled[name].find("nothing that contributes") != std::string::npos);
  }
  CHECK(culled.count("atrous.5+composite") == 0);

  // The debug view reads the variance image: its pass runs then.
  s.scene_moved = true;
  s.debug_view = passes::DebugView::Motion;
  auto g2 = builder.build(s, scene.gpu, scene.targets(16, 16));
  auto compiled2 = runtime.compile(g2);
  REQUIRE(compiled2.culled.size() == 1);
  CHECK(compiled2.culled[0].name == "atrous.5");
}

TEST_CASE(
    "history_tap -1: the temporal pass writes the colour history, no a-trous iteration does, and the frames "
    "run with no report") {
  for (const int tap : {0, -1})
    for (const int local_mean : {-1, 0}) {  // by the size (on), off
      CAPTURE(tap);
      CAPTURE(local_mean);
      Scene scene;
      frame::FrameGraphBuilder builder(scene.device);
      frame::FrameSettings s;
      s.width = 16;
      s.height = 16;
      s.scene_moved = true;
      s.denoise.history_tap = tap;
      s.denoise.local_mean = local_mean;
      scene.gpu.update(4);
      scene.gpu.update(5);
      const auto g = builder.build(s, scene.gpu, scene.targets(16, 16));
      std::vector<std::string> writers;
      bool integrated = false;
      for (const auto& p : g.passes())
        for (const auto& a : p.accesses)
          if (graph::writes(a.use) && !a.history && g.resource(a.resource).name == "color_history")
            writers.push_back(p.name);
      for (const auto& r : g.resources()) integrated = integrated || r.name == "integrated";
      if (tap == -1) {
        CHECK(writers == std::vector<std::string>{"temporal"});
        CHECK_FALSE(integrated);  // the temporal result is the history itself
      } else {
        // With the correction the tapped result is corrected before it becomes the history, by the next
        // iteration, which reads it anyway (atrous.hpp's HistoryCorrection).
        CHECK(writers == std::vector<std::string>{local_mean == 0 ? "atrous.1" : "atrous.2"});
        CHECK(integrated);
      }
      run_frames(scene, s, 3, {}, 4);
      CHECK_MESSAGE(scene.record.reports().empty(), messages(scene.record));
    }
}

TEST_CASE("on a small known graph the derived barriers are exactly the expected ones") {
  CheckedRecord checked;
  hal::Device& device = checked.device;
  graph::GraphRuntime runtime(device);
  graph::RenderGraph g;
  const auto a = g.add_image("a", 4, 4, hal::Format::RGBA16F);
  const auto b = g.add_image("b", 4, 4, hal::Format::RGBA16F);
  const auto h = g.add_image("h", 4, 4, hal::Format::R32F, Lifetime::Persistent);
  g.add_pass("produce").write(a);
  g.add_pass("blur").read(a).read_history(h).write(b);
  g.add_pass("keep").read(a).read(b).write(h);
  g.output(h);
  auto f0 = runtime.compile(g);
  REQUIRE(f0.passes.size() == 3);
  CHECK(f0.passes[0].barriers == std::vector<GraphBarrier>{{a, false, State::Undefined, State::ShaderWrite}});
  CHECK(f0.passes[1].history_clears == std::vector<graph::ResourceId>{h});
  CHECK(f0.passes[1].barriers == std::vector<GraphBarrier>{{a, false, State::ShaderWrite, State::ShaderRead},
                                                           {h, true, State::CopyDst, State::ShaderRead},
                                                           {b, false, State::Undefined, State::ShaderWrite}});
  // No barrier between the two reads of `a`.
  CHECK(f0.passes[2].barriers == std::vector<GraphBarrier>{{b, false, State::ShaderWrite, State::ShaderRead},
                                                           {h, false, State::Undefined, State::ShaderWrite}});
  auto cmd = device.create_command_list("known");
  runtime.execute(f0, *cmd);
  device.submit(*cmd);
  device.wait();
  cmd->reset();
  // Next frame: h's other version, written last frame, is the history; nothing is cleared. The
  // version written now was last frame's history (shader-read) and was never written. The
  // transients take their slots back from last frame: wait for its reads, discard the contents.
  auto f1 = runtime.compile(g);
  CHECK(f1.passes[0].barriers == std::vector<GraphBarrier>{{a, false, State::ShaderRead, State::ShaderWrite, true}});
  CHECK(f1.passes[1].history_clears.empty());
  CHECK(f1.passes[1].barriers == std::vector<GraphBarrier>{{a, false, State::ShaderWrite, State::ShaderRead},
                                                           {h, true, State::ShaderWrite, State::ShaderRead},
                                                           {b, false, State::ShaderRead, State::ShaderWrite, true}});
  CHECK(f1.passes[2].barriers == std::vector<GraphBarrier>{{b, false, State::ShaderWrite, State::ShaderRead},
                                                           {h, false, State::ShaderRead, State::ShaderWrite}});
  runtime.execute(f1, *cmd);
  device.submit(*cmd);
  device.wait();
  CHECK_MESSAGE(checked.record.reports().empty(), messages(checked.record));
}

TEST_CASE("pass traffic: each declared image and sized buffer counts once per pass, read and written separately") {
  CheckedRecord checked;
  graph::GraphRuntime runtime(checked.device);
  graph::RenderGraph g;
  const auto scene = checked.device.create_buffer({"scene", 1000, hal::BufferUsage::Storage});
  const auto counter = checked.device.create_buffer({"counter", 16, hal::BufferUsage::Storage});
  const auto in = g.import("scene", scene, State::ShaderRead);                      // size unknown: uncounted
  const auto count = g.import_buffer("counter", counter, State::ShaderWrite, 16);   // 16 bytes
  const auto a = g.add_image("a", 10, 6, hal::Format::RGBA16F);                     // 480 bytes
  const auto h = g.add_image("h", 10, 6, hal::Format::R32F, Lifetime::Persistent);  // 240 bytes
  const auto out = g.add_image("out", 10, 6, hal::Format::RGBA32F);                 // 960 bytes
  g.add_pass("trace").read(in).write(a).read_write(count);
  g.add_pass("filter").read(a).read_history(h).write(h).write(out);
  g.output(out);
  g.output(count);
  const auto traffic = graph::pass_traffic(runtime.compile(g));
  REQUIRE(traffic.size() == 2);
  CHECK(traffic[0].pass == "trace");
  CHECK(traffic[0].read_bytes == 16);
  CHECK(traffic[0].written_bytes == 480 + 16);
  CHECK(traffic[0].uncounted_reads);
  CHECK(traffic[1].pass == "filter");
  CHECK(traffic[1].read_bytes == 480 + 240);
  CHECK(traffic[1].written_bytes == 240 + 960);
  CHECK_FALSE(traffic[1].uncounted_reads);
  // What the bytes are made of: each access once, in declaration order.
  REQUIRE(traffic[1].resources.size() == 4);
  CHECK(traffic[1].resources[0].name == "a");
  CHECK(traffic[1].resources[0].bytes == 480);
  CHECK(traffic[1].resources[1].name == "h");
  CHECK(traffic[1].resources[1].history);
  CHECK(traffic[1].resources[2].name == "h");
  CHECK((traffic[1].resources[2].written && !traffic[1].resources[2].history));
  CHECK(traffic[1].resources[3].bytes == 960);
  CHECK(traffic[0].resources[0].bytes == 0);  // the scene: size unknown
}

TEST_CASE("history ping-pong: a pass reads last frame's version, cleared on the first frame and after a reset") {
  CheckedRecord checked;
  hal::Device& device = checked.device;
  graph::GraphRuntime runtime(device);
  hal::Resource written[4], read[4];
  bool valid[4];
  for (int f = 0; f < 4; ++f) {
    if (f == 3) runtime.reset_histories();  // a camera cut
    graph::RenderGraph g;
    const auto h = g.add_image("accum", 4, 4, hal::Format::RGBA32F, Lifetime::Persistent);
    g.add_pass("accumulate").read_history(h).write(h).execute([&, h, f](graph::PassContext& ctx) {
      written[f] = ctx.resource(h);
      read[f] = ctx.history(h);
      valid[f] = ctx.history_valid(h);
    });
    g.output(h);
    auto cmd = device.create_command_list("f");
    runtime.execute(runtime.compile(g), *cmd);
    device.submit(*cmd);
    device.wait();
  }
  CHECK_FALSE(valid[0]);
  CHECK(valid[1]);
  CHECK(valid[2]);
  CHECK_FALSE(valid[3]);
  CHECK(read[1] == written[0]);
  CHECK(read[2] == written[1]);
  CHECK_FALSE(written[0] == written[1]);
  CHECK_MESSAGE(checked.record.reports().empty(), messages(checked.record));
}

TEST_CASE("compile errors name the pass and the resource") {
  CheckedRecord checked;
  hal::Device& device = checked.device;
  graph::GraphRuntime runtime(device);
  auto expect_error = [&](const graph::RenderGraph& g, const std::vector<std::string>& words) {
    try {
      runtime.compile(g);
      FAIL("expected a GraphError");
    } catch (const graph::GraphError& e) {
      for (const auto& w : words) CHECK_MESSAGE(std::string(e.what()).find(w) != std::string::npos, e.what());
    }
  };
  {
    graph::RenderGraph g;
    const auto x = g.add_image("never_written", 4, 4, hal::Format::R32F);
    const auto y = g.add_image("out", 4, 4, hal::Format::R32F);
    g.add_pass("consumer").read(x).write(y);
    g.output(y);
    expect_error(g, {"'consumer'", "'never_written'", "no pass writes"});
  }
  {
    graph::RenderGraph g;
    const auto x = g.add_image("x", 4, 4, hal::Format::R32F);
    const auto y = g.add_image("y", 4, 4, hal::Format::R32F);
    g.add_pass("first").read(y).write(x);
    g.add_pass("second").read(x).write(y);
    g.output(y);
    expect_error(g, {"cycle", "'first'", "'second'"});
  }
  {
    graph::RenderGraph g;
    const auto x = g.add_image("shared", 4, 4, hal::Format::R32F);
    g.add_pass("writer_a").write(x);
    g.add_pass("writer_b").write(x);
    g.output(x);
    expect_error(g, {"'writer_a'", "'writer_b'", "'shared'", "no order"});
  }
}

TEST_CASE("aliasing: seeded random graphs never alias two transients whose lifetimes overlap") {
  std::uint64_t with = 0, without = 0;
  for (std::uint32_t seed = 1; seed <= 40; ++seed) {
    CAPTURE(seed);
    std::mt19937 rng(seed);
    CheckedRecord checked;
    hal::Device& device = checked.device;
    graph::GraphRuntime runtime(device);
    graph::RenderGraph g;
    std::vector<graph::ResourceId> made;
    const int passes = 4 + static_cast<int>(rng() % 10);
    for (int p = 0; p < passes; ++p) {
      const auto format = rng() % 2 ? hal::Format::RGBA16F : hal::Format::R32F;
      const auto out = g.add_image("t" + std::to_string(p), 8, 8, format);
      auto builder = g.add_pass("p" + std::to_string(p));
      // Read up to two earlier results, so that lifetimes are of every length.
      for (int k = 0; k < 2 && !made.empty(); ++k) builder.read(made[rng() % made.size()]);
      builder.write(out);
      made.push_back(out);
    }
    g.output(made.back());
    auto compiled = runtime.compile(g);
    const auto& res = g.resources();
    for (std::size_t i = 0; i < res.size(); ++i)
      for (std::size_t j = i + 1; j < res.size(); ++j) {
        const auto& pi = compiled.placement[i];
        const auto& pj = compiled.placement[j];
        if (pi.where != graph::Placement::Where::Transient || pj.where != pi.where || pi.slot != pj.slot) continue;
        const auto li = compiled.lifetime[i], lj = compiled.lifetime[j];
        CHECK_MESSAGE((li.second < lj.first || lj.second < li.first),
                      res[i].name << " and " << res[j].name << " share slot " << pi.slot);
        CHECK(res[i].format == res[j].format);
      }
    CHECK(compiled.memory.transient_with_aliasing <= compiled.memory.transient_without_aliasing);
    with += compiled.memory.transient_with_aliasing;
    without += compiled.memory.transient_without_aliasing;
    auto cmd = device.create_command_list("random");
    runtime.execute(compiled, *cmd);
    device.submit(*cmd);
    device.wait();
    CHECK_MESSAGE(checked.record.reports().empty(), messages(checked.record));
  }
  MESSAGE("transient memory over 40 graphs: " << with << " bytes with aliasing, " << without << " without");
  CHECK(with < without);
}
