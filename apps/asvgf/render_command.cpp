// `asvgf render`: renders an animation with one method and writes every frame as EXR (linear) and
// PNG (tonemapped); with --reference-spp also a reference per frame and metrics.csv.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "commands.hpp"
#include "frame_files.hpp"
#include "io/image_io.hpp"
#include "progress.hpp"
#include "report/metrics.hpp"
#include "scene_options.hpp"

namespace asvgf::cli {
namespace {

struct RenderOptions {
  SceneOptions scene;
  int frames = 0;         // 0: the whole animation
  std::uint32_t spp = 0;  // 0: 1 for the denoisers, 256 for the reference method
  std::uint32_t reference_spp = 0;
  std::string out = "out";
  bool aovs = false;
  bool quiet = false;
};

void write_frame(const std::filesystem::path& dir, const char* prefix, int frame, const render::FrameImages& img) {
  render::write_exr(dir / frame_file(prefix, frame, "exr"), img.width, img.height, img.hdr);
  render::write_png(dir / frame_file(prefix, frame, "png"), img.width, img.height, img.display);
}

// The denoiser's inputs of one frame as `asvgf denoise` reads them (see its --input).
void write_aovs(const std::filesystem::path& dir, int frame, const render::AovImages& a, std::uint32_t w,
                std::uint32_t h) {
  render::write_exr(dir / frame_file("color", frame, "exr"), w, h, a.illumination);
  render::write_exr(dir / frame_file("albedo", frame, "exr"), w, h, a.albedo);
  render::write_exr(dir / frame_file("normal", frame, "exr"), w, h, a.normal);
  render::write_exr(dir / frame_file("depth", frame, "exr"), w, h, a.depth);
  render::write_exr(dir / frame_file("motion", frame, "exr"), w, h, a.motion);
  if (!a.gradient_samples.empty())
    // A marks B as this frame's luminance of the re-shaded sample (asvgf denoise reads that convention).
    render::write_exr(dir / frame_file("gradient", frame, "exr"), (w + 2) / 3, (h + 2) / 3, a.gradient_samples,
                      /*alpha=*/true);
}

int run_render(RenderOptions& o) {
  finish_scene_options(o.scene);
  const scene::Scene scene = load_scene(o.scene);
  const int frames = o.frames > 0 ? o.frames : scene.frame_count;
  auto device = open_device(o.scene);
  render::RenderSettings settings = render_settings(o.scene);
  settings.spp = o.spp > 0 ? o.spp : (settings.method == frame::Method::Reference ? 256 : 1);
  if (o.aovs && settings.method == frame::Method::Reference)
    throw CLI::ValidationError("--aovs", "the reference method has no denoiser inputs; use raw, ema, svgf or asvgf");
  settings.aovs = o.aovs;
  render::Renderer renderer(*device, scene, settings);

  std::unique_ptr<render::Renderer> reference;
  if (o.reference_spp > 0) {
    render::RenderSettings r = settings;
    r.method = frame::Method::Reference;
    r.aovs = false;
    r.spp = o.reference_spp;
    r.seed = settings.seed ^ 0x9e3779b9u;  // independent of the method's noise
    reference = std::make_unique<render::Renderer>(*device, scene, r);
  }

  const std::filesystem::path dir(o.out);
  // No output may replace the scene file or a texture it loaded.
  std::vector<std::pair<std::string, std::filesystem::path>> input_files, output_files;
  if (is_scene_file(o.scene.scene)) input_files.emplace_back("--scene", o.scene.scene);
  for (const auto& t : scene.textures) input_files.emplace_back("--scene (a texture)", t.name);
  for (int f = 0; f < frames; ++f)
    for (const char* prefix : {"frame", "reference", "color", "albedo", "normal", "depth", "motion", "gradient"})
      for (const char* ext : {"exr", "png"}) output_files.emplace_back("--out", dir / frame_file(prefix, f, ext));
  output_files.emplace_back("--out", dir / "metrics.csv");
  refuse_overwriting_inputs(input_files, output_files);
  std::filesystem::create_directories(dir);
  report_stale_partials("render", dir);
  if (!o.quiet)
    std::fprintf(stderr, "asvgf render: %s, %s, %ux%u, %d frames, %u spp%s on %s (%s)\n", scene.name.c_str(),
                 o.scene.method.c_str(), settings.width, settings.height, frames, renderer.spp_per_frame(),
                 reference ? (", reference " + std::to_string(reference->spp_per_frame()) + " spp").c_str() : "",
                 device->adapter().name.c_str(), renderer.ray_query() ? "ray queries" : "software BVH");

  std::vector<std::string> pass_columns;
  std::vector<std::map<std::string, std::string>> rows;
  Progress progress("rendering", frames, o.quiet);
  for (int f = 0; f < frames; ++f) {
    const render::FrameImages img = renderer.render(f);
    write_frame(dir, "frame", f, img);
    if (img.aovs) write_aovs(dir, f, *img.aovs, img.width, img.height);
    std::map<std::string, std::string> row{{"frame", std::to_string(f)}, {"method", o.scene.method}};
    double total = 0.0;
    bool timed = true;
    for (const auto& t : renderer.timings()) {
      if (std::find(pass_columns.begin(), pass_columns.end(), t.pass) == pass_columns.end())
        pass_columns.push_back(t.pass);
      timed = timed && t.gpu_ms.has_value();
      total += t.gpu_ms.value_or(0.0);
      row[t.pass] = t.gpu_ms ? std::to_string(*t.gpu_ms) : "";
    }
    row["gpu_ms"] = timed ? std::to_string(total) : "";
    std::string note;
    if (reference) {
      const render::FrameImages ref = reference->render(f);
      write_frame(dir, "reference", f, ref);
      const double relmse = render::relative_mse(img.hdr, ref.hdr);
      row["relmse"] = std::to_string(relmse);
      row["ssim"] = std::to_string(render::ssim(img.hdr, ref.hdr, img.width, img.height));
      note = "relMSE " + std::to_string(relmse);
    }
    rows.push_back(std::move(row));
    progress.step(f + 1, note);
  }

  if (reference) {
    std::ostringstream csv;
    csv << "frame,method,relmse,ssim,gpu_ms";
    for (const auto& p : pass_columns) csv << "," << p << "_ms";
    csv << "\n";
    for (auto& row : rows) {
      csv << row["frame"] << "," << row["method"] << "," << row["relmse"] << "," << row["ssim"] << "," << row["gpu_ms"];
      for (const auto& p : pass_columns) csv << "," << row[p];
      csv << "\n";
    }
    write_metrics_csv(dir, csv.str());
  }
  const auto sanitised = renderer.dropped_samples();
  if (!o.quiet) {
    std::fprintf(stderr,
                 "sanitised: %u samples with NaN and %u with Inf dropped before the histories, %u clamped to the "
                 "fp16 maximum 65504, %u output pixels written as 0 (not finite)\n",
                 sanitised.nan_samples, sanitised.inf_samples, sanitised.clamped_samples, sanitised.zeroed_outputs);
    std::fprintf(stderr, "results: %s/frame_NNNN.{exr,png}%s%s\n", dir.string().c_str(),
                 reference ? ", reference_NNNN.{exr,png}, metrics.csv" : "",
                 o.aovs ? (", denoiser inputs {color,albedo,normal,depth,motion}_NNNN.exr" +
                           std::string(settings.method == frame::Method::Asvgf ? ", gradient_NNNN.exr" : ""))
                              .c_str()
                        : "");
  }
  return 0;
}

}  // namespace

std::function<int()> add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand("render", "Render an animation with one method; write EXR and PNG frames");
  add_scene_options(*cmd, o->scene);
  cmd->add_option("--frames", o->frames, "Frames to render (default: the whole animation)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--spp", o->spp, "Samples per pixel per frame (default 1; 256 for --method reference)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--reference-spp", o->reference_spp,
                  "Also render a reference with this many spp per frame and write metrics.csv")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--out", o->out, "Output folder")->capture_default_str();
  cmd->add_flag("--aovs", o->aovs,
                "Also write the denoiser's inputs per frame (color = demodulated radiance, albedo, normal, depth, "
                "motion; gradient samples for asvgf) as EXR, for `asvgf denoise --input`");
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  return [o] { return run_render(*o); };
}

}  // namespace asvgf::cli
