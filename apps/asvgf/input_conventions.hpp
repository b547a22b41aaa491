// How `asvgf denoise` reads another renderer's frames: which file channels hold each buffer (one
// file per buffer, or one multilayer file per frame holding every pass), whether the colour is
// radiance or already demodulated, and the motion vectors' convention. Presets: `--from cycles`
// (Blender Cycles' multilayer EXR), `--from pbrt` (pbrt-v4's "gbuffer" film, which writes no motion
// vectors: a still sequence) and ours (asvgf render --aovs).
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "asvgf/denoiser.hpp"

namespace asvgf::cli {

struct InputConventionOptions {
  std::string from;                                 // "", "cycles", "pbrt"
  std::vector<std::string> channels;                // BUFFER=C1,C2,... (repeatable)
  bool demodulated = false;                         // --demodulated: the colour is radiance / albedo
  bool still = false;                               // --still: nothing moves; no motion files
  std::string motion_preset;                        // ours, cycles, nrd ("": the --from preset's, else ours)
  std::string motion_sign, motion_units, motion_y;  // overrides of the preset ("" = the preset's)
};

void add_input_convention_options(CLI::App& cmd, InputConventionOptions& o);

struct InputConventions {
  // File channel names per buffer (color, albedo, normal, depth, motion, reference); a buffer not
  // listed is read as R, G, B(, A) by name.
  std::map<std::string, std::vector<std::string>> channels;
  ColorInput color = ColorInput::Radiance;
  MotionConvention motion;
  bool still = false;            // no motion files: every motion vector is 0 (camera and scene hold still)
  std::string describe() const;  // e.g. "radiance, motion previous minus current in pixels, y up"
};

// Whether the options say the sequence holds still (--still, or --from pbrt without --motion).
bool still_sequence(const InputConventionOptions& o, bool motion_given);

// The conventions the options name. `cycles_layer` is the view layer found in the first frame's
// file ("ViewLayer"), used by --from cycles; `still` is still_sequence's answer. Throws
// CLI::ValidationError naming the option.
InputConventions resolve_input_conventions(const InputConventionOptions& o, bool own_folder,
                                           const std::string& cycles_layer, bool still);

// The view layer of a Cycles multilayer file: the prefix of its "<layer>.Combined.R" channel.
std::string cycles_layer_of(const std::vector<std::string>& channels);

// The option text that selects `motion` (for messages naming the fix).
std::string motion_options(const MotionConvention& motion);

}  // namespace asvgf::cli
