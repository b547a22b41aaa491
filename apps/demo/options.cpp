#include "options.hpp"

#include <cstdio>

namespace asvgf::demo {

const char* const kControlsHelp =
    "Controls:\n"
    "  arrow keys, PageUp/PageDown  move the sphere light (left/right, up/down, away/towards)\n"
    "  left mouse drag              move the sphere light in the image plane\n"
    "  right mouse drag             orbit the camera around its target; mouse wheel: dolly\n"
    "  1 2 3 4 5                    method: raw, ema, svgf, asvgf, reference (accumulates while still)\n"
    "  V / Shift+V                  next / previous buffer: final, normals, depth, motion, albedo, noisy input,\n"
    "                               temporal gradient, alpha, variance, history length (heat maps)\n"
    "  + / -                        one more / one fewer a-trous iteration (0..10)\n"
    "  space                        pause / resume the animation\n"
    "  R                            restart the animation; the light and camera follow it again\n"
    "  P                            save a screenshot PNG (the shown buffer; its name is printed)\n"
    "  H                            print these controls\n"
    "  Esc                          quit\n";

const std::vector<ViewEntry>& views() {
  using passes::DebugView;
  static const std::vector<ViewEntry> all = {
      {"final", std::nullopt},          {"normals", DebugView::Normals}, {"depth", DebugView::Depth},
      {"motion", DebugView::Motion},    {"albedo", DebugView::Albedo},   {"noisy", DebugView::NoisyInput},
      {"gradient", DebugView::Gradient}, {"alpha", DebugView::Alpha},    {"variance", DebugView::Variance},
      {"history", DebugView::HistoryLength},
  };
  return all;
}

std::optional<std::size_t> view_index(const std::string& name) {
  for (std::size_t i = 0; i < views().size(); ++i)
    if (name == views()[i].name) return i;
  return std::nullopt;
}

void add_demo_options(CLI::App& app, DemoOptions& o) {
  o.scene.animation = "static";  // the demo's default: the user moves the light
  cli::add_scene_options(app, o.scene);
  app.add_option("--spp", o.spp, "Samples per pixel per frame")->check(CLI::Range(1, 1024))->capture_default_str();
  app.add_option("--window", o.window, "Initial window size WIDTHxHEIGHT (default: the render size scaled up to >= 512)");
  app.add_flag("--fit-window", o.fit_window,
               "Render at the window's size (the renderer is recreated on resize); default: render at --size and "
               "scale to the window");
  std::string names;
  for (const auto& v : views()) names += std::string(names.empty() ? "" : ", ") + v.name;
  app.add_option("--view", o.view, "Buffer shown first: " + names)->capture_default_str()->check([](const std::string& s) {
    return view_index(s) ? std::string() : "unknown view '" + s + "'";
  });
  app.add_option("--frames", o.frames, "Render this many frames, then exit (0: run until closed)")
      ->check(CLI::Range(0, 1000000));
  app.add_option("--screenshot", o.screenshot, "On exit, save the last frame shown as this PNG");
  app.add_option("--screenshot-dir", o.screenshot_dir, "Folder for the P key's screenshots")->capture_default_str();
  app.add_option("--resize-at", o.resize_at, "Test hook: resize the window to WxH before frame K")
      ->expected(2)
      ->type_name("K WxH");
  app.add_option("--resize-storm", o.resize_storm,
                 "Test hook: resize the window before each of the first N frames, cycling through four sizes; "
                 "every tenth of them also minimises, restores and hides the window for one frame")
      ->check(CLI::Range(0, 100000));
  app.add_flag("--no-vsync", o.no_vsync, "Present without waiting for vertical sync");
  app.footer(kControlsHelp);
}

void finish(DemoOptions& o) {
  cli::finish_scene_options(o.scene);
  o.scene.backend = cli::chosen_backend(o.scene.backend);  // --backend, else $ASVGF_BACKEND (checked here)
  if (!o.window.empty()) o.window_size = cli::parse_size_option("--window", o.window);
  if (!o.resize_at.empty()) {
    try {
      o.resize_frame = std::stoi(o.resize_at.at(0));
    } catch (const std::exception&) {
      throw CLI::ValidationError("--resize-at", "'" + o.resize_at.at(0) + "' is not a frame number");
    }
    if (o.resize_frame < 0) throw CLI::ValidationError("--resize-at", "the frame must be >= 0");
    o.resize_to = cli::parse_size_option("--resize-at", o.resize_at.at(1));
  }
}

}  // namespace asvgf::demo
