// demo/options.hpp: asvgf-demo's command line (the asvgf tool's scene and denoiser options plus the
// window, the scripted runs and the test hooks) and the key list shown by --help and the H key.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "renderer/render_passes.hpp"
#include "scene_options.hpp"

namespace asvgf::demo {

using Size = cli::ImageSize;

struct DemoOptions {
  cli::SceneOptions scene;
  std::uint32_t spp = 1;         // samples per pixel per frame (the reference accumulates them)
  std::string window;            // initial window size; empty: the render size scaled up to >= 512
  bool fit_window = false;       // render at the window's size (renderer recreated on resize)
  std::string view = "final";    // first buffer shown
  int frames = 0;                // > 0: render this many frames, then exit (scripts, tests)
  std::string screenshot;        // with --frames: PNG of the last frame
  std::string screenshot_dir = ".";  // where P saves
  std::vector<std::string> resize_at;  // test hook: {"K", "WxH"}
  int resize_storm = 0;                // test hook: resize the window before each of the first N frames
  bool no_vsync = false;

  // Parsed from the strings above by finish().
  std::optional<Size> window_size;
  int resize_frame = -1;
  Size resize_to;
};

// The buffers V cycles through; nullopt is the final image.
struct ViewEntry {
  const char* name;
  std::optional<passes::DebugView> view;
};
const std::vector<ViewEntry>& views();
std::optional<std::size_t> view_index(const std::string& name);

// The keys and mouse buttons, one per line (the --help footer and the H key print it).
extern const char* const kControlsHelp;

void add_demo_options(CLI::App& app, DemoOptions& options);
// Checks what CLI11 cannot (WxH syntax, --screenshot needing --frames); throws CLI::ValidationError.
void finish(DemoOptions& options);

}  // namespace asvgf::demo
