// `asvgf report`: renders one animation with every method and setting (raw, EMA 0.2 and 0.05, SVGF,
// A-SVGF with the default and the seed's à-trous settings, plain accumulation at 1, 2, 4, ... spp),
// measures each frame against a reference and writes report.md, report.csv and PNG plots.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "frame_files.hpp"
#include "io/atomic_file.hpp"
#include "progress.hpp"
#include "renderer/scene/builtin.hpp"
#include "renderer/scene/scene.hpp"
#include "report/metrics.hpp"
#include "report/report.hpp"
#include "report/summary.hpp"
#include "report_runs.hpp"
#include "scene_options.hpp"

namespace asvgf::cli {
namespace {

struct ReportOptions {
  SceneOptions scene;
  int frames = 0;  // 0: the whole animation
  std::string methods;
  std::vector<std::string> runs;  // --run: runs of the user's own settings
  std::string scenes;             // --scenes: several scenes and a summary; empty: --scene only
  std::uint32_t reference_spp = 512;
  std::uint32_t max_accumulation_spp = 64;
  std::string out = "out/report";
  std::string timing = "auto";
  bool quiet = false;
};

// GPU time of the frame just rendered: the sum of its passes and the passes themselves; the sum
// is empty when any pass has no timestamp.
struct FrameTime {
  std::optional<double> total;
  std::vector<std::pair<std::string, double>> passes;
};
FrameTime frame_time(const render::Renderer& renderer) {
  FrameTime t;
  bool timed = !renderer.timings().empty();
  double total = 0;
  for (const auto& p : renderer.timings()) {
    timed = timed && p.gpu_ms.has_value();
    if (p.gpu_ms) t.passes.emplace_back(p.pass, *p.gpu_ms), total += *p.gpu_ms;
  }
  if (timed) t.total = total;
  return t;
}

// The run's frames again, back to back with nothing read back, after at least half a second of
// warm-up renders: a GPU lowers its clock while it idles, as it does between the frames of the
// quality pass (their host work takes longer than their GPU work), which would slow short frames
// most (docs/quality.md has the difference measured on a GPU).
std::vector<FrameTime> time_back_to_back(hal::Device& device, const scene::Scene& scene, render::RenderSettings s,
                                         int frames) {
  s.read_back = false;
  render::Renderer renderer(device, scene, s);
  const auto warm_start = std::chrono::steady_clock::now();
  for (int i = 0; i < 2 || std::chrono::steady_clock::now() - warm_start < std::chrono::milliseconds(500); ++i)
    renderer.render(0);
  std::vector<FrameTime> times;
  for (int f = 0; f < frames; ++f) {
    renderer.render(f);  // frame 0 after frame 0 starts afresh, as the quality pass did
    times.push_back(frame_time(renderer));
  }
  return times;
}

// The part of the image the crops show: all of it when small, else a window near the top right
// (where the light of light-exit sits and leaves).
struct CropRegion {
  std::uint32_t x = 0, y = 0, w = 0, h = 0;
};
CropRegion crop_region(std::uint32_t width, std::uint32_t height) {
  constexpr std::uint32_t kMax = 160;
  CropRegion r{0, 0, std::min(width, kMax), std::min(height, kMax)};
  if (width > kMax) r.x = std::min(width - kMax, std::uint32_t(0.68 * width) - kMax / 2);
  if (height > kMax)
    r.y = std::min(height - kMax, std::uint32_t(0.3 * height) > kMax / 2 ? std::uint32_t(0.3 * height) - kMax / 2 : 0u);
  return r;
}
report::CropCell crop(const std::vector<std::uint8_t>& rgba, std::uint32_t width, const CropRegion& r) {
  report::CropCell c{std::vector<std::uint8_t>(std::size_t(r.w) * r.h * 4), r.w, r.h};
  for (std::uint32_t y = 0; y < r.h; ++y)
    std::copy_n(&rgba[((std::size_t(r.y) + y) * width + r.x) * 4], std::size_t(r.w) * 4,
                &c.rgba[std::size_t(y) * r.w * 4]);
  return c;
}

// Where reflections change most: the crop-sized window holding the largest luminance change, over
// the pixels `mask` marks, between the reference `before` and `after` (RGBA float images). Scans
// window positions 8 pixels apart with a summed-area table.
CropRegion most_changed_region(const std::vector<float>& before, const std::vector<float>& after,
                               const std::vector<std::uint8_t>& mask, std::uint32_t width, std::uint32_t height,
                               CropRegion size) {
  std::vector<double> sum((std::size_t(width) + 1) * (height + 1), 0.0);
  auto at = [&](std::uint32_t x, std::uint32_t y) -> double& { return sum[std::size_t(y) * (width + 1) + x]; };
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::size_t p = std::size_t(y) * width + x;
      double change = 0;
      if (mask[p])
        for (int c = 0; c < 3; ++c) change += std::abs(double(after[4 * p + c]) - double(before[4 * p + c]));
      at(x + 1, y + 1) = change + at(x, y + 1) + at(x + 1, y) - at(x, y);
    }
  CropRegion best = size;
  double best_change = -1;
  for (std::uint32_t y = 0; y + size.h <= height; y += 8)
    for (std::uint32_t x = 0; x + size.w <= width; x += 8) {
      const double c = at(x + size.w, y + size.h) - at(x, y + size.h) - at(x + size.w, y) + at(x, y);
      if (c > best_change) best_change = c, best.x = x, best.y = y;
    }
  return best;
}

std::string command_line(const ReportOptions& o, int frames) {
  std::string s = "asvgf report --scene " + o.scene.scene + " --animation " + o.scene.animation + " --size " +
                  o.scene.size + " --frames " + std::to_string(frames) + " --reference-spp " +
                  std::to_string(o.reference_spp) + " --max-accumulation-spp " +
                  std::to_string(o.max_accumulation_spp) + " --seed " + std::to_string(o.scene.seed);
  if (!o.methods.empty()) s += " --methods " + o.methods;
  for (const auto& r : o.runs) s += " --run '" + r + "'";
  if (o.scene.software_bvh) s += " --software-bvh";
  if (!default_backend_chosen(o.scene.backend)) s += " --backend " + chosen_backend(o.scene.backend);
  if (o.timing != "auto") s += " --timing " + o.timing;
  return s;
}

// Per frame, what each pixel sees, from the G-buffer the denoiser sees (rendered once a frame):
// its class (report/pixel_classes.hpp) and, against the same scene with some material property
// dropped, whether that property shows there (its albedo, what the denoiser divides by, differs
// exactly there). Dropping textures marks textured surfaces (a texel of exactly 1 would read as
// untextured; the built-in textures stay below); dropping the GGX lobe marks glossy ones (their
// albedo is the lobes' directional albedo, not the base colour).
struct PixelMaps {
  std::vector<std::vector<report::PixelClass>> classes;
  std::vector<std::vector<std::uint8_t>> textured, glossy;  // empty without `untextured`, `matte`
};
PixelMaps pixel_maps(hal::Device& device, const scene::Scene& scene, const std::optional<scene::Scene>& untextured,
                     const std::optional<scene::Scene>& matte, render::RenderSettings s, int frames) {
  s.method = frame::Method::Raw;
  s.spp = 1;
  s.aovs = true;
  render::Renderer with(device, scene, s);
  std::optional<render::Renderer> without_textures, without_gloss;
  if (untextured) without_textures.emplace(device, *untextured, s);
  if (matte) without_gloss.emplace(device, *matte, s);
  auto mask = [](const render::FrameImages& a, const render::FrameImages& b) {
    std::vector<std::uint8_t> m(std::size_t(a.width) * a.height, 0);
    for (std::size_t p = 0; p < m.size(); ++p)
      for (int c = 0; c < 3; ++c)
        if (std::abs(a.aovs->albedo[4 * p + c] - b.aovs->albedo[4 * p + c]) > 1e-4f) m[p] = 1;
    return m;
  };
  PixelMaps maps;
  for (int f = 0; f < frames; ++f) {
    const auto a = with.render(f);
    maps.classes.push_back(report::classify_pixels(a.aovs->albedo, a.aovs->depth, a.aovs->normal, a.width, a.height));
    if (without_textures) maps.textured.push_back(mask(a, without_textures->render(f)));
    if (without_gloss) maps.glossy.push_back(mask(a, without_gloss->render(f)));
  }
  return maps;
}

// One scene's report, written to `dir` (report.md, report.csv, plots).
report::SceneReport report_scene(const ReportOptions& o, std::vector<report::RunSpec> specs, hal::Device& device,
                                 const std::filesystem::path& dir) {
  const auto start = std::chrono::steady_clock::now();
  const scene::Scene scene = load_scene(o.scene);
  // The report writes many files into `dir` (plots among them): it refuses a folder that holds the
  // scene file or a texture it loaded rather than risk replacing one.
  std::vector<std::pair<std::string, std::filesystem::path>> inputs;
  if (is_scene_file(o.scene.scene)) inputs.emplace_back("--scene", o.scene.scene);
  for (const auto& t : scene.textures) inputs.emplace_back("--scene (a texture)", t.name);
  refuse_folder_holding_inputs("--out", dir, inputs);
  // Without glossy materials there is one signal anyway: the built-in split run would repeat its
  // twin (a --run asking for the split is rendered all the same).
  if (std::none_of(scene.materials.begin(), scene.materials.end(), [](const auto& m) { return m.glossy(); }))
    std::erase_if(specs, [](const report::RunSpec& s) { return s.specular_split && !s.own; });
  if (specs.empty())
    throw CLI::ValidationError(
        "--methods", "the runs chosen need glossy materials (asvgf-split), and scene '" + scene.name + "' has none");
  const int frames = o.frames > 0 ? o.frames : scene.frame_count;
  const render::RenderSettings base = render_settings(o.scene);

  report::ReportData d;
  d.scene = scene.name;
  d.animation = o.scene.animation;
  d.width = base.width, d.height = base.height, d.seed = base.seed, d.frames = frames;
  d.device_name = device.adapter().name;
  if (!default_backend_chosen(o.scene.backend)) d.device_name += ", " + device.adapter().api_version;
  d.device_type = std::string(hal::to_string(device.adapter().type));
  d.cpu_device = device.adapter().type == hal::DeviceType::Cpu;
  d.timestamps = device.capabilities().timestamps;
  d.timed_separately = d.timestamps && (o.timing == "separate" || (o.timing == "auto" && !d.cpu_device));
  d.command_line = command_line(o, frames);

  // Frames with the scene state of the frame before share its reference render.
  std::vector<bool> changed(std::size_t(frames), false);
  std::vector<int> group(std::size_t(frames), 0);
  scene::FrameState previous = scene::evaluate(scene, 0.0f);
  for (int f = 1; f < frames; ++f) {
    const scene::FrameState s = scene::evaluate(scene, float(f));
    changed[std::size_t(f)] = !scene::same_state(s, previous);
    group[std::size_t(f)] = group[std::size_t(f) - 1] + (changed[std::size_t(f)] ? 1 : 0);
    previous = s;
  }
  d.change = report::find_change(changed);
  d.reference_renders = group.back() + 1;

  // Frames shown as crops: before, during and after the change, and the last.
  std::set<int> shown, stored;
  if (d.change) {
    shown = {d.change->first - 1, (d.change->first + d.change->last) / 2, d.change->last + 1, frames - 1};
    for (int f = d.change->first - 1; f <= d.change->last + 3; ++f) stored.insert(f);
  } else {
    shown = {1, frames / 2, frames - 1};
  }
  for (int f : shown)
    if (f >= 0 && f < frames) d.crop_frames.push_back(f), stored.insert(f);
  std::erase_if(stored, [&](int f) { return f < 0 || f >= frames; });
  const CropRegion region = crop_region(d.width, d.height);
  d.crop_zoom = std::max(1, int(std::lround(192.0 / std::max(region.w, region.h))));
  auto region_note = [&](const CropRegion& r) {
    return r.w == d.width && r.h == d.height ? "whole image, " + std::to_string(d.crop_zoom) + "x"
                                             : std::to_string(r.w) + "x" + std::to_string(r.h) + " crop at (" +
                                                   std::to_string(r.x) + "," + std::to_string(r.y) + ")";
  };
  d.crop_note = region_note(region);

  Progress progress("report", d.reference_renders + int(specs.size()) * frames, o.quiet);
  int done = 0;
  if (!o.quiet)
    std::fprintf(stderr, "asvgf report: %s, %ux%u, %d frames, %zu runs, reference %u spp x %d renders on %s\n",
                 scene.name.c_str(), d.width, d.height, frames, specs.size(), o.reference_spp, d.reference_renders,
                 d.device_name.c_str());

  auto fraction = [&](const std::vector<std::vector<std::uint8_t>>& masks) {
    std::size_t count = 0;
    for (const auto& m : masks) count += std::size_t(std::count(m.begin(), m.end(), std::uint8_t(1)));
    return double(count) / (double(d.width) * d.height * frames);
  };
  const auto& materials = scene.materials;
  std::optional<scene::Scene> untextured, matte;
  if (std::any_of(materials.begin(), materials.end(), [](const auto& m) { return m.albedo_texture >= 0; })) {
    untextured = scene;
    for (auto& m : untextured->materials) m.albedo_texture = -1;
  }
  if (std::any_of(materials.begin(), materials.end(), [](const auto& m) { return m.glossy(); })) {
    matte = scene;
    for (auto& m : matte->materials) m.metallic = m.specular = 0.0f;
  }
  progress.step(done, "classing the pixels");
  const PixelMaps maps = pixel_maps(device, scene, untextured, matte, base, frames);
  const auto& textured = maps.textured;
  const auto& glossy = maps.glossy;
  const auto& classes = maps.classes;
  if (!textured.empty()) d.textured_fraction = fraction(textured);
  if (!glossy.empty()) d.glossy_fraction = fraction(glossy);

  std::vector<std::vector<float>> reference(std::size_t(d.reference_renders));
  std::vector<std::vector<std::uint8_t>> reference_display(reference.size());  // scenes with glossy materials
  std::vector<double> reference_mean(reference.size());
  {
    render::RenderSettings r = base;
    r.method = frame::Method::Reference;
    r.spp = o.reference_spp;
    r.seed = base.seed ^ 0x9e3779b9u;  // independent of every method's noise
    render::Renderer renderer(device, scene, r);
    d.reference_spp = renderer.spp_per_frame();
    d.ray_query = renderer.ray_query();
    for (int f = 0; f < frames; ++f) {
      const std::size_t gi = std::size_t(group[std::size_t(f)]);
      if (f > 0 && gi == std::size_t(group[std::size_t(f) - 1])) continue;
      render::FrameImages img = renderer.render(f);
      reference_mean[gi] = render::mean_value(img.hdr);
      reference[gi] = std::move(img.hdr);
      d.reference_crops[f] = crop(img.display, d.width, region);
      if (!glossy.empty() && d.change) reference_display[gi] = std::move(img.display);
      progress.step(++done, "reference frame " + std::to_string(f));
    }
  }
  // Crops of frames that share a reference render: copy them from the render's first frame.
  for (int f : stored) {
    int g0 = f;
    while (g0 > 0 && group[std::size_t(g0)] == group[std::size_t(g0) - 1]) --g0;
    d.reference_crops[f] = d.reference_crops[g0];
  }
  std::erase_if(d.reference_crops, [&](const auto& e) { return !stored.count(e.first); });

  // Glossy scenes that change: a second crop where the reflections change most, for ghosting.
  std::optional<CropRegion> glossy_region;
  if (!glossy.empty() && d.change && d.change->first > 0) {
    const int before = d.change->first - 1, after = d.change->last;
    glossy_region = most_changed_region(reference[std::size_t(group[std::size_t(before)])],
                                        reference[std::size_t(group[std::size_t(after)])], glossy[std::size_t(after)],
                                        d.width, d.height, region);
    d.glossy_crop_note = region_note(*glossy_region);
    for (int f : stored)
      d.reference_glossy_crops[f] =
          crop(reference_display[std::size_t(group[std::size_t(f)])], d.width, *glossy_region);
  }
  reference_display.clear();

  for (const auto& spec : specs) {
    render::RenderSettings s = base;
    s.method = spec.method;
    s.spp = spec.spp;
    s.denoise = spec.denoise;
    s.demodulate = spec.demodulate;
    s.specular_split = spec.specular_split;
    render::Renderer renderer(device, scene, s);
    report::RunResult run;
    run.spec = spec;
    std::vector<float> prev;
    report::ErrorMap error_map = spec.accumulation() ? report::ErrorMap{} : report::error_map(d.width, d.height);
    for (int f = 0; f < frames; ++f) {
      render::FrameImages img = renderer.render(f);
      const std::size_t gi = std::size_t(group[std::size_t(f)]);
      const auto& ref = reference[gi];
      report::FrameResult fr;
      fr.frame = f;
      fr.relmse = render::relative_mse(img.hdr, ref);
      if (!spec.accumulation()) report::add_frame(error_map, img.hdr, ref);
      fr.ssim = render::ssim(img.hdr, ref, d.width, d.height);
      fr.temporal =
          f > 0 ? report::temporal_error(img.hdr, prev, ref, reference[std::size_t(group[std::size_t(f) - 1])]) : NAN;
      fr.mean = render::mean_value(img.hdr);
      if (!textured.empty()) {
        fr.relmse_textured = render::relative_mse(img.hdr, ref, textured[std::size_t(f)], true);
        fr.relmse_untextured = render::relative_mse(img.hdr, ref, textured[std::size_t(f)], false);
      }
      if (!glossy.empty()) {
        fr.relmse_glossy = render::relative_mse(img.hdr, ref, glossy[std::size_t(f)], true);
        fr.relmse_matte = render::relative_mse(img.hdr, ref, glossy[std::size_t(f)], false);
      }
      fr.classes = report::relmse_by_class(img.hdr, ref, classes[std::size_t(f)]);
      fr.reference_mean = reference_mean[gi];
      if (!d.timed_separately) {
        FrameTime t = frame_time(renderer);
        fr.gpu_ms = t.total;
        fr.pass_ms = std::move(t.passes);
      }
      if (stored.count(f)) run.crops[f] = crop(img.display, d.width, region);
      if (stored.count(f) && glossy_region) run.glossy_crops[f] = crop(img.display, d.width, *glossy_region);
      run.frames.push_back(std::move(fr));
      prev = std::move(img.hdr);
      char note[96];
      std::snprintf(note, sizeof note, "%s frame %d relMSE %.3g", spec.name.c_str(), f, run.frames.back().relmse);
      progress.step(++done, note);
    }
    if (d.timed_separately) {
      progress.step(done, spec.name + ": timing the frames back to back");
      std::vector<FrameTime> times = time_back_to_back(device, scene, s, frames);
      for (int f = 0; f < frames; ++f) {
        run.frames[std::size_t(f)].gpu_ms = times[std::size_t(f)].total;
        run.frames[std::size_t(f)].pass_ms = std::move(times[std::size_t(f)].passes);
      }
    }
    if (!spec.accumulation())
      run.error_map = report::shrink(error_map, report::shrink_factor(d.width, report::kErrorMapWidth));
    report::summarise(run, d.change);
    d.runs.push_back(std::move(run));
  }

  d.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const report::Headline headline = report::compute_headline(d);
  std::filesystem::create_directories(dir);
  report_stale_partials("report", dir);
  report::write_plots(d, headline, dir);
  render::write_file_atomic(dir / "report.csv", report::report_csv(d));
  render::write_file_atomic(dir / "report.md", report::report_markdown(d, headline));
  if (!o.quiet) {
    std::fprintf(stderr, "%s\n", headline.text.c_str());
    std::fprintf(stderr, "report: %s (report.csv and PNG plots beside it), %.0f s\n",
                 (dir / "report.md").string().c_str(), d.wall_seconds);
  }
  return {std::move(d), headline, dir.filename().string()};
}

// --scenes: a comma list of built-in scene names or scene files, or "all" (every built-in scene).
std::vector<std::string> scene_list(const std::string& list) {
  if (list == "all") return scene::builtin_scenes();
  std::vector<std::string> names;
  std::stringstream ss(list);
  std::string token;
  const auto builtin = scene::builtin_scenes();
  while (std::getline(ss, token, ',')) {
    if (token.empty()) continue;
    const bool file = is_scene_file(token);
    if (!file && std::find(builtin.begin(), builtin.end(), token) == builtin.end()) {
      std::string valid;
      for (const auto& n : builtin) valid += (valid.empty() ? "" : ", ") + n;
      throw CLI::ValidationError(
          "--scenes", "'" + token + "' is neither a built-in scene (" + valid + ", or all) nor a scene file (.json)");
    }
    // Each scene's report goes to OUT/<file stem>: two names with one stem would share a folder.
    const std::string stem = std::filesystem::path(token).stem().string();
    for (const std::string& other : names)
      if (std::filesystem::path(other).stem().string() == stem)
        throw CLI::ValidationError("--scenes", "'" + token + "' and '" + other + "' would both write to " + stem +
                                                   "/ (list each scene once, file names distinct)");
    names.push_back(token);
  }
  if (names.empty()) throw CLI::ValidationError("--scenes", "names no scene");
  return names;
}

int run_report(ReportOptions& o) {
  finish_scene_options(o.scene);
  const auto builtin = builtin_runs(o.max_accumulation_spp);
  auto specs = select_runs(builtin, o.methods);
  std::vector<report::RunSpec> taken = builtin;
  for (const std::string& text : o.runs) {
    specs.push_back(parse_run(text, taken));
    taken.push_back(specs.back());
  }
  const std::filesystem::path out(o.out);
  if (o.scenes.empty()) {
    auto device = open_device(o.scene);
    report_scene(o, specs, *device, out);
    return 0;
  }
  const std::vector<std::string> names = scene_list(o.scenes);
  auto device = open_device(o.scene);
  std::vector<report::SceneReport> reports;
  for (const std::string& name : names) {
    ReportOptions one = o;
    one.scene.scene = name;
    if (!o.quiet)
      std::fprintf(stderr, "asvgf report: scene %zu of %zu: %s\n", reports.size() + 1, names.size(), name.c_str());
    reports.push_back(report_scene(one, specs, *device, out / std::filesystem::path(name).stem()));
  }
  std::filesystem::create_directories(out);
  render::write_file_atomic(out / "summary.csv", report::summary_csv(reports));
  render::write_file_atomic(out / "summary.md", report::summary_markdown(reports));
  if (!o.quiet) std::fprintf(stderr, "summary: %s (summary.csv beside it)\n", (out / "summary.md").string().c_str());
  return 0;
}

}  // namespace

std::function<int()> add_report_command(CLI::App& app) {
  auto o = std::make_shared<ReportOptions>();
  o->scene.size = "64x64";
  auto* cmd = app.add_subcommand("report", "Error against GPU time for every method: report.md, report.csv, PNG plots");
  auto& s = o->scene;
  cmd->add_option("--scene", s.scene, "Built-in scene (cornell, glossy, textured, many) or a scene file (.json)")
      ->capture_default_str();
  auto* scenes = cmd->add_option("--scenes", o->scenes,
                                 "Comma list of scenes (built-in names or .json files) or 'all': a report for each in "
                                 "OUT/<scene>/ and summary.md/summary.csv over them in OUT");
  scenes->excludes("--scene");
  cmd->add_option("--animation", s.animation, "Animation of the built-in scene")
      ->check(CLI::IsMember(scene::builtin_animations()))
      ->capture_default_str();
  cmd->add_option("--size", s.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--frames", o->frames, "Frames (default: the whole animation)")->check(CLI::Range(2, 100000));
  cmd->add_option("--methods", o->methods,
                  "Comma list restricting the runs: raw, ema, svgf, asvgf, reference (or accum), or run names "
                  "(ema-0.05, asvgf-box9, accum-4spp, ...)");
  cmd->add_option("--run", o->runs,
                  "A run of your own, NAME=METHOD [OPTIONS], added to the runs --methods picks (repeat it for "
                  "more): METHOD raw, ema, svgf or asvgf; OPTIONS those of `asvgf render` that tune the "
                  "denoiser (--sigma-l, --history-tap, --alpha, ..., --no-demodulation, --specular-split), "
                  "e.g. --run 'asvgf-sl8=asvgf --sigma-l 8'")
      ->type_size(1)
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--reference-spp", o->reference_spp, "Samples per pixel of the reference")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--max-accumulation-spp", o->max_accumulation_spp,
                  "Plain accumulation at 1, 2, 4, ... up to this spp")
      ->check(CLI::Range(1, 1 << 16))
      ->capture_default_str();
  cmd->add_option("--seed", s.seed, "Random seed: the same seed gives the same numbers")->capture_default_str();
  add_backend_option(*cmd, s);
  cmd->add_option("--device", s.device,
                  "Vulkan adapter: index or part of its name (default: $ASVGF_DEVICE, else best)");
  cmd->add_flag("--software-bvh", s.software_bvh, "Trace with the software BVH even where ray queries exist");
  cmd->add_option("--timing", o->timing,
                  "GPU time of each frame: 'separate' renders every run again back to back, nothing read back (an "
                  "idle GPU lowers its clock between the frames of the quality pass); 'inline' times the quality "
                  "pass's frames; 'auto': separate on GPUs, inline on CPU devices")
      ->check(CLI::IsMember({"auto", "inline", "separate"}))
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Output folder")->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  return [o] { return run_report(*o); };
}

}  // namespace asvgf::cli
