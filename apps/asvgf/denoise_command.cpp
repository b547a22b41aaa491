// `asvgf denoise`: denoises a frame sequence rendered elsewhere (per-buffer EXR sequences, in the
// manner of Intel Open Image Denoise's command line, plus depth, motion and A-SVGF's gradient
// samples) through the public API (include/asvgf/denoiser.hpp), and writes every frame as EXR and
// PNG; with --reference also metrics.csv. `asvgf render --aovs` writes exactly these buffers.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "asvgf/denoiser.hpp"
#include "color_check.hpp"
#include "commands.hpp"
#include "frame_files.hpp"
#include "frame_sequence.hpp"
#include "input_conventions.hpp"
#include "io/half_float.hpp"
#include "io/image_io.hpp"
#include "motion_check.hpp"
#include "noise_check.hpp"
#include "progress.hpp"
#include "report/metrics.hpp"
#include "scene_options.hpp"

namespace asvgf::cli {
namespace {

struct DenoiseOptions {
  SceneOptions device;  // backend, adapter, validation and the denoiser parameters
  std::string method = "asvgf";
  std::string input;  // a folder of `asvgf render --aovs`
  std::string color, albedo, normal, depth, motion, gradient, reference;
  bool depth_gradient = false;
  bool motion_check = true;
  bool noise_check = true;
  bool validate = false;
  int first = 0;
  int frames = 0;  // 0: as many as --color has from --first-frame on
  std::string out = "denoised";
  bool quiet = false;
  InputConventionOptions conventions;
  const CLI::Option* gradient_source_option = nullptr;  // to tell an explicit --gradient-source from the default
  bool color_from_folder = false;                       // --color filled from a render --aovs folder: demodulated
  const CLI::Option* first_option = nullptr;            // --first-frame given?
};

// --input DIR fills every pattern not given explicitly with DIR/<buffer>_%04d.exr (the gradient
// only for asvgf, and only when DIR has one for the first frame) and reads the depth gradient.
// With --from cycles or pbrt, --input is the files' pattern (one file a frame holds every buffer)
// and fills every buffer's (pbrt's files hold no motion).
void apply_input_folder(DenoiseOptions& o) {
  if (o.input.empty()) return;
  if (!o.conventions.from.empty()) {
    for (std::string* pattern : {&o.color, &o.albedo, &o.normal, &o.depth})
      if (pattern->empty()) *pattern = o.input;
    if (o.conventions.from == "cycles" && o.motion.empty()) o.motion = o.input;
    return;
  }
  const std::filesystem::path dir(o.input);
  if (!std::filesystem::is_directory(dir))
    throw CLI::ValidationError("--input", "'" + o.input + "' is not a folder (one written by asvgf render --aovs)");
  auto fill = [&](std::string& pattern, const char* buffer) {
    if (pattern.empty()) pattern = (dir / (std::string(buffer) + "_%04d.exr")).string();
  };
  // Depth files from render --aovs hold the depth gradient in G; a --depth given beside --input may not.
  if (o.depth.empty()) o.depth_gradient = true;
  o.color_from_folder = o.color.empty();
  fill(o.color, "color");
  fill(o.albedo, "albedo");
  fill(o.normal, "normal");
  fill(o.depth, "depth");
  fill(o.motion, "motion");
  if (o.method == "asvgf" && o.device.gradient_source == "reshaded" && o.gradient.empty() &&
      std::filesystem::exists(dir / frame_file("gradient", o.first, "exr")))
    fill(o.gradient, "gradient");
}

// True when some stratum holds a gradient sample (index 0..8); false: nothing moved this frame.
bool has_gradient_samples(const render::ExrImage& image) {
  for (std::size_t i = 1; i < image.rgba.size(); i += 4)
    if (image.rgba[i] >= 0.0f && image.rgba[i] < 9.0f) return true;
  return false;
}

// Whether a gradient file's samples carry this frame's re-shaded luminance in B (render --aovs
// marks them with A = 1: DenoiserConfig::gradient_current_given), or leave it to the colour's pixel
// (A 0 or absent: older files, RG samples). Nothing when no stratum holds a sample; refused when
// the strata disagree.
std::optional<bool> gradient_current_marked(const render::ExrImage& image, const std::string& what) {
  const auto has = [&](const char* c) {
    return std::find(image.channels.begin(), image.channels.end(), c) != image.channels.end();
  };
  const bool channels = has("B") && has("A");
  std::optional<bool> marked;
  for (std::size_t i = 1; i + 2 < image.rgba.size(); i += 4) {
    if (!(image.rgba[i] >= 0.0f && image.rgba[i] < 9.0f)) continue;
    const bool m = channels && image.rgba[i + 2] == 1.0f;
    if (marked && *marked != m)
      throw render::ImageIoError(what +
                                 ": channel A marks some strata's B as this frame's luminance (1) and "
                                 "not others: expected 1 on every stratum with a sample, or on none");
    marked = m;
  }
  return marked;
}

int run_denoise(DenoiseOptions& o) {
  o.device.size = "1x1";  // the frames set the size
  finish_scene_options(o.device);
  apply_input_folder(o);
  const bool still = still_sequence(o.conventions, !o.motion.empty());
  for (const auto& [name, value] : {std::pair{"--color", &o.color},
                                    {"--albedo", &o.albedo},
                                    {"--normal", &o.normal},
                                    {"--depth", &o.depth},
                                    {"--motion", &o.motion}})
    if (value->empty() && !(still && value == &o.motion))
      throw CLI::ValidationError(name, std::string("is required (or --input DIR from asvgf render --aovs") +
                                           (value == &o.motion ? "; --still when nothing moves)" : ")"));
  if (!o.gradient.empty() && o.method != "asvgf")
    throw CLI::ValidationError("--gradient", "gradient samples are for --method asvgf only");
  if (!o.gradient.empty() && o.device.gradient_source == "reprojected")
    throw CLI::ValidationError("--gradient", "--gradient-source reprojected estimates the gradient itself");

  const FramePattern color("--color", o.color), albedo("--albedo", o.albedo), normal("--normal", o.normal),
      depth("--depth", o.depth), motion = still ? FramePattern() : FramePattern("--motion", o.motion);
  const FramePattern gradient = o.gradient.empty() ? FramePattern() : FramePattern("--gradient", o.gradient);
  const FramePattern reference = o.reference.empty() ? FramePattern() : FramePattern("--reference", o.reference);
  // asvgf needs a temporal gradient: without re-shaded samples it estimates one from reprojected
  // luminance, and says so; --gradient-source reshaded without samples is refused (constant alpha
  // is --method svgf).
  std::string gradient_note;
  bool gradient_chosen = false;  // the reprojected gradient chosen for the user: said even with --quiet
  if (o.method == "asvgf" && gradient.empty() && o.device.gradient_source == "reshaded") {
    if (o.gradient_source_option && o.gradient_source_option->count() > 0)
      throw CLI::ValidationError("--gradient-source",
                                 "reshaded needs gradient samples (--gradient, or gradient_NNNN.exr "
                                 "in --input); reprojected needs none; --method svgf is constant "
                                 "alpha");
    o.device.gradient_source = "reprojected";
    o.device.denoise.gradient_source = GradientSource::Reprojected;
    gradient_note = "reprojected (no gradient samples given)";
    gradient_chosen = true;
  } else if (o.method == "asvgf") {
    gradient_note = o.device.gradient_source == "reprojected" ? "reprojected" : "reshaded samples";
  }

  // Without --first-frame the sequence starts at its lowest frame (Blender numbers from 1).
  if (o.first_option && o.first_option->count() == 0)
    if (const auto lowest = color.lowest_frame()) o.first = *lowest;
  const int available = count_frames(color, o.first, o.frames);
  if (available == 0)
    throw render::ImageIoError(color.path(o.first).string() + " (color, frame " + std::to_string(o.first) +
                               "): missing; nothing to denoise");
  const int frames = o.frames > 0 ? o.frames : available;
  if (frames > available)
    throw render::ImageIoError(color.path(o.first + available).string() + " (color, frame " +
                               std::to_string(o.first + available) + "): missing; --frames asks for " +
                               std::to_string(frames));

  const std::string cycles_layer = o.conventions.from == "cycles"
                                       ? cycles_layer_of(render::read_exr_header(color.path(o.first)).channels)
                                       : std::string();
  const InputConventions conventions =
      resolve_input_conventions(o.conventions, o.color_from_folder, cycles_layer, still);
  auto channels_of = [&](const char* buffer) {
    const auto it = conventions.channels.find(buffer);
    return it == conventions.channels.end() ? std::vector<std::string>{} : it->second;
  };
  const render::ExrImage first =
      read_frame(color, o.first, {"color", 0, 0, {"R", "G", "B"}, false, channels_of("color")});
  const std::uint32_t w = first.width, h = first.height, gw = (w + 2) / 3, gh = (h + 2) / 3;
  auto device = open_device(o.device);
  asvgf::DenoiserConfig config;
  config.width = w;
  config.height = h;
  config.method = o.method == "ema"    ? DenoiseMethod::Ema
                  : o.method == "svgf" ? DenoiseMethod::Svgf
                                       : DenoiseMethod::Asvgf;
  config.settings = o.device.denoise;
  config.depth_gradient_given = o.depth_gradient;
  // The gradient files' convention, from the first that holds a sample (each frame's is checked).
  const BufferSpec gradient_spec{"gradient", gw, gh, {"R", "G"}};
  auto gradient_file = [&](int f) {
    return gradient.path(f).string() + " (gradient, frame " + std::to_string(f) + ")";
  };
  for (int i = 0; i < frames && !gradient.empty(); ++i) {
    if (!std::filesystem::exists(gradient.path(o.first + i))) continue;  // reported when its frame is read
    if (const auto marked =
            gradient_current_marked(read_frame(gradient, o.first + i, gradient_spec), gradient_file(o.first + i))) {
      config.gradient_current_given = *marked;
      break;
    }
  }
  config.color_input = conventions.color;
  config.motion = conventions.motion;
  config.validate = o.validate;
  asvgf::Denoiser denoiser(*device, config);

  const auto usage =
      hal::ImageUsage::Sampled | hal::ImageUsage::Storage | hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst;
  auto create = [&](const char* name, std::uint32_t iw, std::uint32_t ih, hal::Format format) {
    return device->create_image({name, iw, ih, format, usage});
  };
  const hal::Format F32 = hal::Format::RGBA32F;
  struct Input {
    const FramePattern* pattern;
    BufferSpec spec;
    hal::ImageHandle image;
  };
  // Specs first, images one by one: with the creations inside the braced list, a creation that
  // threw crashed the unwinding (GCC 12 freed a string of the list twice; found by the fault sweep).
  std::vector<Input> inputs = {
      {&color, {"color", w, h, {"R", "G", "B"}, false, channels_of("color")}, {}},
      {&albedo, {"albedo", w, h, {"R", "G", "B"}, false, channels_of("albedo")}, {}},
      {&normal, {"normal", w, h, {"R", "G", "B"}, false, channels_of("normal")}, {}},
      {&depth,
       {"depth", w, h, o.depth_gradient ? std::vector<std::string>{"R", "G"} : std::vector<std::string>{"R"},
        /*infinity_allowed=*/true, channels_of("depth")},
       {}},
      {&motion, {"motion", w, h, {"R", "G"}, false, channels_of("motion")}, {}},
  };
  for (auto& in : inputs) in.image = create(in.spec.name.c_str(), w, h, F32);
  constexpr std::size_t kMotion = 4;
  if (still) {  // one upload of zeros serves every frame
    const std::vector<float> zeros(std::size_t(w) * h * 4);
    device->upload_image(inputs[kMotion].image, std::as_bytes(std::span(zeros)));
  }
  const hal::ImageHandle gradient_image = gradient.empty() ? hal::ImageHandle{} : create("gradient", gw, gh, F32);
  // Half floats, as asvgf render writes these methods' radiance: the histories are half floats, the
  // input is clamped to 65504, and the output rounds to the nearest half (8 bytes a pixel less).
  const hal::Format radiance_format = hal::Format::RGBA16F;
  const hal::ImageHandle radiance = create("radiance", w, h, radiance_format);
  std::vector<std::uint16_t> hdr_halves(std::size_t(w) * h * 4);
  const hal::ImageHandle display = create("display", w, h, hal::Format::RGBA8Unorm);

  const std::filesystem::path dir(o.out);
  // Before anything is written: no output may replace an input of this run (the references
  // included, which are read after the frame they measure is written).
  std::vector<std::pair<std::string, std::filesystem::path>> input_files, output_files;
  for (int i = 0; i < frames; ++i) {
    const int f = o.first + i;
    for (const FramePattern* p : {&color, &albedo, &normal, &depth, &motion, &gradient, &reference})
      if (!p->empty()) input_files.emplace_back(p->option(), p->path(f));
    output_files.emplace_back("--out", dir / frame_file("frame", f, "exr"));
    output_files.emplace_back("--out", dir / frame_file("frame", f, "png"));
  }
  if (!reference.empty()) output_files.emplace_back("--out", dir / "metrics.csv");
  refuse_overwriting_inputs(input_files, output_files);
  // Every frame's files by their headers (not their pixels), before anything is written: a file of
  // another size or an unreadable one late in the sequence stops the run here, not after the
  // frames before it were written.
  for (int i = 0; i < frames; ++i) {
    std::set<std::filesystem::path> checked;  // --from cycles: one file holds every buffer
    for (const Input& in : inputs)
      if (!in.pattern->empty() && checked.insert(in.pattern->path(o.first + i)).second)
        check_frame_header(*in.pattern, o.first + i, in.spec);
    if (!gradient.empty()) check_frame_header(gradient, o.first + i, gradient_spec);
    if (!reference.empty() && checked.insert(reference.path(o.first + i)).second)
      check_frame_header(reference, o.first + i, {"reference", w, h});
  }
  std::filesystem::create_directories(dir);
  report_stale_partials("denoise", dir);
  if (!o.quiet)
    std::fprintf(stderr, "asvgf denoise: %d frames of %ux%u from %s (%s), %s%s%s on %s\n", frames, w, h,
                 o.color.c_str(), conventions.describe().c_str(), o.method.c_str(),
                 gradient_note.empty() ? "" : ", gradient: ", gradient_note.c_str(), device->adapter().name.c_str());
  else if (gradient_chosen)
    std::fprintf(stderr, "asvgf denoise: asvgf's gradient: %s\n", gradient_note.c_str());

  std::ostringstream csv;
  csv << "frame,method,relmse,ssim,gpu_ms,gradient\n";
  Progress progress("denoising", frames, o.quiet);
  std::vector<float> hdr(std::size_t(w) * h * 4);
  std::vector<std::uint8_t> ldr(std::size_t(w) * h * 4);
  std::vector<float> previous_depth, previous_color;
  for (int i = 0; i < frames; ++i) {
    const int f = o.first + i;
    std::vector<render::ExrImage> images;
    for (auto& in : inputs) {
      if (in.pattern->empty()) {  // still: the zeros uploaded once
        images.emplace_back();
        continue;
      }
      images.push_back(read_frame(*in.pattern, f, in.spec));
      device->upload_image(in.image, std::as_bytes(std::span(images.back().rgba)));
    }
    render::ExrImage& depth_now = images[3];
    if (i == 0 && o.validate) {
      const ColorKindCheck kind =
          check_color_kind(images[0].rgba, images[1].rgba, depth_now.rgba, conventions.color == ColorInput::Radiance);
      if (kind.problem) std::fprintf(stderr, "%sframe %d: %s\n", o.quiet ? "" : "\n", f, kind.problem->c_str());
    }
    // The vectors in the denoiser's convention, as the GPU converts them (asvgf::motion_scale), for
    // both checks; none when still.
    std::vector<float> vectors;
    if (i > 0 && !still && (o.motion_check || o.noise_check)) {
      const auto scale = motion_scale(conventions.motion, w, h);
      vectors = images[kMotion].rgba;
      for (std::size_t k = 0; k < vectors.size(); k += 4) vectors[k] *= scale[0], vectors[k + 1] *= scale[1];
    }
    if (i > 0 && o.motion_check && !still) {
      const MotionCheck check = check_motion(previous_depth, depth_now.rgba, vectors, w, h, conventions.motion);
      if (check.problem)
        throw render::ImageIoError(motion.path(f).string() + " (motion, frame " + std::to_string(f) +
                                   "): " + *check.problem + " (--no-motion-check skips this test)");
    }
    if (i > 0 && o.noise_check) {
      const RepeatedNoiseCheck check =
          check_repeated_noise(previous_color, images[0].rgba, previous_depth, depth_now.rgba, vectors, w, h);
      if (check.problem)
        throw render::ImageIoError(color.path(f).string() + " (colour, frame " + std::to_string(f) +
                                   "): " + *check.problem + " (--no-noise-check denoises it anyway)");
    }
    previous_depth = std::move(depth_now.rgba);
    if (o.noise_check) previous_color = images[0].rgba;
    std::optional<DenoiserImage> samples;
    if (!gradient.empty()) {
      const render::ExrImage img = read_frame(gradient, f, gradient_spec);
      const auto marked = gradient_current_marked(img, gradient_file(f));
      if (marked && *marked != config.gradient_current_given)
        throw render::ImageIoError(gradient_file(f) + ": channel A " +
                                   (*marked ? "marks B as this frame's luminance" : "does not mark B") +
                                   ", unlike the sequence's first gradient samples");
      if (has_gradient_samples(img)) {
        device->upload_image(gradient_image, std::as_bytes(std::span(img.rgba)));
        samples = DenoiserImage{gradient_image, F32, hal::State::CopyDst};
      }
    }
    const auto uploaded = hal::State::CopyDst;
    const auto after = i == 0 ? hal::State::Undefined : hal::State::CopySrc;
    denoiser.denoise({{inputs[0].image, F32, uploaded},
                      {inputs[1].image, F32, uploaded},
                      {inputs[2].image, F32, uploaded},
                      {inputs[3].image, F32, uploaded},
                      {inputs[kMotion].image, F32, still && i > 0 ? hal::State::ShaderRead : uploaded},
                      samples},
                     {{radiance, radiance_format, after},
                      DenoiserImage{display, hal::Format::RGBA8Unorm, after},
                      hal::State::CopySrc});
    device->read_image(radiance, std::as_writable_bytes(std::span(hdr_halves)));
    std::transform(hdr_halves.begin(), hdr_halves.end(), hdr.begin(), io::half_to_float);
    device->read_image(display, std::as_writable_bytes(std::span(ldr)));
    render::write_exr(dir / frame_file("frame", f, "exr"), w, h, hdr);
    render::write_png(dir / frame_file("frame", f, "png"), w, h, ldr);

    if (o.validate)
      for (const auto& problem : denoiser.input_report().problems)
        std::fprintf(stderr, "%sframe %d: %s\n", o.quiet ? "" : "\n", f, problem.c_str());
    double gpu_ms = 0;
    bool timed = true;
    for (const auto& t : denoiser.timings()) {
      timed = timed && t.gpu_ms.has_value();
      gpu_ms += t.gpu_ms.value_or(0.0);
    }
    std::string note;
    if (!reference.empty()) {
      const render::ExrImage ref =
          read_frame(reference, f, {"reference", w, h, {"R", "G", "B"}, false, channels_of("reference")});
      const double relmse = render::relative_mse(hdr, ref.rgba);
      csv << f << "," << o.method << "," << std::to_string(relmse) << ","
          << std::to_string(render::ssim(hdr, ref.rgba, w, h)) << "," << (timed ? std::to_string(gpu_ms) : "") << ","
          << gradient_note << "\n";
      note = "relMSE " + std::to_string(relmse);
    }
    progress.step(i + 1, note);
  }
  if (!reference.empty()) write_metrics_csv(dir, csv.str());
  for (auto& in : inputs) device->destroy(in.image);
  if (gradient_image) device->destroy(gradient_image);
  device->destroy(radiance);
  device->destroy(display);

  const auto s = denoiser.sanitised();
  if (!o.quiet) {
    std::fprintf(stderr,
                 "sanitised: %u samples with NaN and %u with Inf dropped, %u clamped to the fp16 maximum 65504, %u "
                 "output pixels written as 0 (not finite)\n",
                 s.nan_samples, s.inf_samples, s.clamped_samples, s.zeroed_outputs);
    std::fprintf(stderr, "results: %s/frame_NNNN.{exr,png}%s\n", dir.string().c_str(),
                 reference.empty() ? "" : ", metrics.csv");
  }
  return 0;
}

}  // namespace

std::function<int()> add_denoise_command(CLI::App& app) {
  auto o = std::make_shared<DenoiseOptions>();
  auto* cmd = app.add_subcommand(
      "denoise",
      "Denoise a frame sequence from per-buffer EXR files (e.g. from asvgf render --aovs); write EXR and PNG");
  cmd->add_option(
      "--input", o->input,
      "Folder written by asvgf render --aovs (reads its {color,albedo,normal,depth,motion,gradient}_NNNN.exr, "
      "colour demodulated); with --from cycles or pbrt the pattern of the renderer's files (one a frame)");
  cmd->add_option("--color", o->color,
                  "Noisy radiance (RGB; --demodulated: divided by the albedo), e.g. frames/color_%04d.exr");
  cmd->add_option("--albedo", o->albedo, "Albedo (RGB): the denoiser divides the radiance by it and multiplies back");
  cmd->add_option("--normal", o->normal, "World-space normals (RGB = xyz; 0 = background)");
  cmd->add_option("--depth", o->depth,
                  "Linear view depth in R (0 = background); G = its gradient with --depth-gradient");
  cmd->add_option("--motion", o->motion,
                  "Motion vectors (RG): previous minus current position in pixels, y down (other conventions: "
                  "--motion-convention and --motion-sign/-units/-y)");
  cmd->add_option("--gradient", o->gradient,
                  "A-SVGF gradient samples, ceil(w/3) x ceil(h/3): R = last frame's luminance, G = pixel 0..8 in the "
                  "3x3 stratum or -1 (include/asvgf/denoiser.hpp)");
  cmd->add_flag("--depth-gradient", o->depth_gradient, "The depth files' G channel holds max(|dz/dx|, |dz/dy|)");
  cmd->add_flag("!--no-motion-check", o->motion_check,
                "Do not test whether the motion vectors follow the convention (checked from frame to frame: the "
                "previous frame's depth where they point should match)");
  cmd->add_flag("!--no-noise-check", o->noise_check,
                "Do not test whether the noise repeats from frame to frame (a renderer's seed that is not animated: "
                "still pixels bit-identical to the previous frame's)");
  cmd->add_flag("--validate", o->validate,
                "Also check every frame's inputs on the GPU against the conventions and print what is wrong "
                "(asvgf::DenoiserConfig::validate)");
  cmd->add_option("--reference", o->reference, "Reference frames (RGB radiance): also write metrics.csv");
  cmd->add_option("--method", o->method, "ema, svgf or asvgf")
      ->check(CLI::IsMember({"ema", "svgf", "asvgf"}))
      ->capture_default_str();
  cmd->add_option("--first-frame", o->first, "Number of the first frame (default: the lowest --color has)")
      ->check(CLI::Range(0, 99999999));
  cmd->add_option("--frames", o->frames, "Frames to denoise (default: every frame --color has from the first on)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--out", o->out, "Output folder")->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress output");
  add_input_convention_options(*cmd, o->conventions);
  add_device_options(*cmd, o->device);
  add_denoise_options(*cmd, o->device);
  o->gradient_source_option = cmd->get_option("--gradient-source");
  o->first_option = cmd->get_option("--first-frame");
  return [o] { return run_denoise(*o); };
}

}  // namespace asvgf::cli
