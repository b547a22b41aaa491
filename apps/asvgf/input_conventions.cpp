#include "input_conventions.hpp"

#include <set>

namespace asvgf::cli {
namespace {

const std::set<std::string> kBuffers = {"color", "albedo", "normal", "depth", "motion", "reference"};

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == separator) {
      parts.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  return parts;
}

const char* units_name(MotionUnits u) {
  return u == MotionUnits::Pixels ? "pixels" : u == MotionUnits::Uv ? "uv" : "ndc";
}

}  // namespace

void add_input_convention_options(CLI::App& cmd, InputConventionOptions& o) {
  cmd.add_option("--from", o.from,
                 "Read another renderer's output as it writes it: cycles (Blender's multilayer EXR, one file a frame "
                 "holding every pass; --input is then its file pattern, e.g. 'frames/%04d.exr'), pbrt (pbrt-v4's "
                 "\"gbuffer\" film with \"coordinatesystem\" \"camera\": one EXR a frame; it writes no motion "
                 "vectors, so the sequence must hold still unless --motion is given)")
      ->check(CLI::IsMember({"cycles", "pbrt"}));
  cmd.add_option("--channels", o.channels,
                 "BUFFER=C1,C2,...: the file channels holding a buffer (color, albedo, normal, depth, motion, "
                 "reference), e.g. 'normal=View Layer.Normal.X,View Layer.Normal.Y,View Layer.Normal.Z' (repeatable)");
  cmd.add_flag("--demodulated", o.demodulated,
               "--color holds radiance already divided by the albedo (default: radiance; asvgf render --aovs "
               "folders are read as demodulated)");
  cmd.add_flag("--still", o.still,
               "Nothing moves (camera and scene): no --motion files, every motion vector is 0 (implied by --from "
               "pbrt without --motion)");
  cmd.add_option("--motion-convention", o.motion_preset,
                 "Motion vectors as written by: ours (previous minus current, pixels, y down), cycles (y up), nrd "
                 "(previous minus current in UV units)")
      ->check(CLI::IsMember({"ours", "cycles", "nrd"}));
  cmd.add_option("--motion-sign", o.motion_sign,
                 "previous-minus-current or current-minus-previous (overrides the preset)")
      ->check(CLI::IsMember({"previous-minus-current", "current-minus-previous"}));
  cmd.add_option("--motion-units", o.motion_units, "pixels, uv or ndc (overrides the preset)")
      ->check(CLI::IsMember({"pixels", "uv", "ndc"}));
  cmd.add_option("--motion-y", o.motion_y, "down or up: where +y points (overrides the preset)")
      ->check(CLI::IsMember({"down", "up"}));
}

std::string cycles_layer_of(const std::vector<std::string>& channels) {
  const std::string suffix = ".Combined.R";
  for (const auto& c : channels)
    if (c.size() > suffix.size() && c.compare(c.size() - suffix.size(), suffix.size(), suffix) == 0)
      return c.substr(0, c.size() - suffix.size());
  return "";
}

bool still_sequence(const InputConventionOptions& o, bool motion_given) {
  if (o.still && motion_given) throw CLI::ValidationError("--still", "says nothing moves: leave out --motion");
  return o.still || (o.from == "pbrt" && !motion_given);
}

InputConventions resolve_input_conventions(const InputConventionOptions& o, bool own_folder,
                                           const std::string& cycles_layer, bool still) {
  InputConventions c;
  c.still = still;
  if (o.from == "cycles") {
    if (cycles_layer.empty())
      throw CLI::ValidationError("--from",
                                 "cycles: the first frame has no '<layer>.Combined.R' channel (is it a "
                                 "multilayer EXR with the Combined pass?)");
    auto pass = [&](const std::string& name, const char* components) {
      std::vector<std::string> names;
      for (const char* k = components; *k; ++k) names.push_back(cycles_layer + "." + name + "." + *k);
      return names;
    };
    c.channels["color"] = pass("Combined", "RGB");
    c.channels["reference"] = pass("Combined", "RGB");
    c.channels["albedo"] = pass("Denoising Albedo", "RGB");
    c.channels["normal"] = pass("Normal", "XYZ");
    c.channels["depth"] = pass("Depth", "Z");
    c.channels["motion"] = pass("Vector", "XY");
    c.motion = MotionConvention::cycles();
  }
  if (o.from == "pbrt") {
    // pbrt-v4's GBufferFilm (src/pbrt/film.cpp): R, G, B radiance, Albedo.R/G/B, the shading normal
    // Nsx/Nsy/Nsz, the position Px/Py/Pz (camera space with "coordinatesystem" "camera": pbrt's
    // camera looks down +z, so Pz is the view depth; 0 where no surface was hit, our background).
    c.channels["color"] = {"R", "G", "B"};
    c.channels["reference"] = {"R", "G", "B"};
    c.channels["albedo"] = {"Albedo.R", "Albedo.G", "Albedo.B"};
    c.channels["normal"] = {"Nsx", "Nsy", "Nsz"};
    c.channels["depth"] = {"Pz"};
  }
  for (const auto& entry : o.channels) {
    const auto eq = entry.find('=');
    const std::string buffer = eq == std::string::npos ? "" : entry.substr(0, eq);
    if (!kBuffers.count(buffer))
      throw CLI::ValidationError("--channels",
                                 "'" + entry +
                                     "' is not BUFFER=C1,C2,... with BUFFER one of color, albedo, normal, "
                                     "depth, motion, reference");
    const auto names = split(entry.substr(eq + 1), ',');
    if (names.empty() || names.size() > 4 || std::any_of(names.begin(), names.end(), [](auto& n) { return n.empty(); }))
      throw CLI::ValidationError("--channels", "'" + entry + "' names 1 to 4 channels, none empty");
    c.channels[buffer] = names;
  }
  if (own_folder || o.demodulated) c.color = ColorInput::Demodulated;
  if (o.motion_preset == "ours") c.motion = MotionConvention::ours();
  if (o.motion_preset == "cycles") c.motion = MotionConvention::cycles();
  if (o.motion_preset == "nrd") c.motion = MotionConvention::nrd();
  if (!o.motion_sign.empty()) c.motion.previous_minus_current = o.motion_sign == "previous-minus-current";
  if (!o.motion_units.empty())
    c.motion.units = o.motion_units == "pixels" ? MotionUnits::Pixels
                     : o.motion_units == "uv"   ? MotionUnits::Uv
                                                : MotionUnits::Ndc;
  if (!o.motion_y.empty()) c.motion.y_up = o.motion_y == "up";
  return c;
}

std::string motion_options(const MotionConvention& m) {
  return std::string("--motion-sign ") +
         (m.previous_minus_current ? "previous-minus-current" : "current-minus-previous") + " --motion-units " +
         units_name(m.units) + " --motion-y " + (m.y_up ? "up" : "down");
}

std::string InputConventions::describe() const {
  const std::string kind = color == ColorInput::Radiance ? "radiance" : "demodulated colour";
  if (still) return kind + ", still (no motion)";
  return kind + ", motion " + (motion.previous_minus_current ? "previous minus current" : "current minus previous") +
         " in " + units_name(motion.units) + ", y " + (motion.y_up ? "up" : "down");
}

}  // namespace asvgf::cli
