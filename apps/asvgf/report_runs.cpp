// `asvgf report`'s runs (report_runs.hpp).
#include "report_runs.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <set>
#include <sstream>

#include "scene_options.hpp"

namespace asvgf::cli {

std::vector<report::RunSpec> builtin_runs(std::uint32_t max_accumulation_spp) {
  using frame::Method;
  std::vector<report::RunSpec> runs;
  auto add = [&](std::string name, std::string what, Method m, auto&& tweak) {
    report::RunSpec s;
    s.name = std::move(name);
    s.description = std::move(what);
    s.method = m;
    tweak(s);
    runs.push_back(s);
  };
  auto none = [](report::RunSpec&) {};
  add("raw", "1 spp, no filter", Method::Raw, none);
  add("ema-0.2", "EMA, constant α 0.2, no spatial filter", Method::Ema, none);
  add("ema-0.05", "EMA, constant α 0.05 (ghosting)", Method::Ema, [](report::RunSpec& s) {
    s.denoise.alpha = 0.05f;
    s.summarised = false;
  });
  add("svgf", "SVGF: constant α 0.2, 5 à-trous iterations (B3, 13 taps)", Method::Svgf, none);
  add("asvgf", "A-SVGF: adaptive α, 5 à-trous iterations (B3, 13 taps)", Method::Asvgf, none);
  add("asvgf-reproj", "A-SVGF, gradient from reprojected noisy luminance (no re-shading; Q2RTX's LF)", Method::Asvgf,
      [](report::RunSpec& s) { s.denoise.gradient_source = asvgf::GradientSource::Reprojected; });
  add("asvgf-nodemod", "A-SVGF filtering radiance with the albedo in it (--no-demodulation)", Method::Asvgf,
      [](report::RunSpec& s) { s.demodulate = false; });
  add("asvgf-split", "A-SVGF filtering diffuse and specular light apart (--specular-split)", Method::Asvgf,
      [](report::RunSpec& s) { s.specular_split = true; });
  add("asvgf-box9", "A-SVGF, the seed's 3x3 box kernel, 9 iterations", Method::Asvgf, [](report::RunSpec& s) {
    s.denoise.kernel = asvgf::AtrousKernel::Box;
    s.denoise.atrous_iterations = 9;
    s.summarised = false;
  });
  add("asvgf-box15", "A-SVGF, the seed's 3x3 box kernel, 15 iterations", Method::Asvgf, [](report::RunSpec& s) {
    s.denoise.kernel = asvgf::AtrousKernel::Box;
    s.denoise.atrous_iterations = 15;
    s.summarised = false;
  });
  for (std::uint32_t spp = 1; spp <= max_accumulation_spp; spp *= 2)
    add("accum-" + std::to_string(spp) + "spp", "plain accumulation, " + std::to_string(spp) + " spp a frame",
        Method::Reference, [spp](report::RunSpec& s) { s.spp = spp; });
  return runs;
}

std::vector<report::RunSpec> select_runs(std::vector<report::RunSpec> runs, const std::string& list) {
  if (list.empty()) return runs;
  std::vector<report::RunSpec> picked;
  std::stringstream ss(list);
  std::string token;
  std::set<std::string> names;
  while (std::getline(ss, token, ',')) {
    if (token.empty()) continue;
    bool any = false;
    for (const auto& r : runs) {
      const std::string method(frame::to_string(r.method));
      if (r.name == token || method == token || (token == "accum" && r.accumulation())) {
        any = true;
        names.insert(r.name);
      }
    }
    if (!any)
      throw CLI::ValidationError("--methods", "'" + token +
                                                  "' names no run: use raw, ema, svgf, asvgf, reference (accum) "
                                                  "or a run name such as ema-0.05, asvgf-box9, accum-4spp");
  }
  for (const auto& r : runs)
    if (names.count(r.name)) picked.push_back(r);
  return picked;
}

namespace {

bool name_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
         c == '.' || c == '+';
}

}  // namespace

report::RunSpec parse_run(const std::string& text, const std::vector<report::RunSpec>& taken) {
  auto refuse = [&](const std::string& problem) { return CLI::ValidationError("--run", "'" + text + "': " + problem); };
  const auto equals = text.find('=');
  if (equals == std::string::npos) throw refuse("expected NAME=METHOD [OPTIONS], e.g. 'asvgf-sl8=asvgf --sigma-l 8'");
  const std::string name = text.substr(0, equals);
  if (name.empty() || !std::all_of(name.begin(), name.end(), name_character))
    throw refuse("the name '" + name + "' must be letters, digits and - _ . + (it names the run in report.csv)");
  for (const auto& r : taken)
    if (r.name == name) throw refuse("the name '" + name + "' is already a run's (pick another)");
  std::istringstream words(text.substr(equals + 1));
  std::string method;
  words >> method;
  report::RunSpec spec;
  spec.name = name;
  spec.own = true;
  // Plain accumulation has its own runs (accum-<spp>), with no denoiser settings to vary.
  const auto parsed = frame::method_from_string(method);
  if (!parsed || *parsed == frame::Method::Reference)
    throw refuse("the method '" + method + "' is not raw, ema, svgf or asvgf");
  spec.method = *parsed;
  std::string options, word;
  while (words >> word) options += (options.empty() ? "" : " ") + word;
  // The options and their checks are `asvgf render`'s: one list, one range check.
  SceneOptions scene;
  CLI::App parser("--run options", "--run");
  add_denoise_options(parser, scene);
  parser.add_flag("--no-demodulation", scene.no_demodulation, "Filter radiance, albedo included");
  add_specular_options(parser, scene);
  parser.allow_extras(false);
  try {
    parser.parse(options, false);
    scene.size = "1x1";  // finish_scene_options parses it; the report's own --size sets the frames
    finish_scene_options(scene);
  } catch (const CLI::Error& e) {
    throw refuse(e.what());
  }
  spec.denoise = scene.denoise;
  spec.demodulate = !scene.no_demodulation;
  spec.specular_split = scene.specular_split;
  spec.description =
      method + (options.empty() ? std::string(" with the default settings") : " " + options) + " (--run)";
  return spec;
}

}  // namespace asvgf::cli
