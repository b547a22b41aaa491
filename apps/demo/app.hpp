// demo/app.hpp: the demo's window and frame loop: input -> scene and settings -> Renderer ->
// presenter, with the title as overlay, screenshots, resizes and minimising.
//
// Presentation: the Renderer leaves its display (or debug-view) image on the GPU in CopySrc
// (RenderSettings::read_back = false); the app moves it to State::Present, the backend's presenter
// blits it (linear filter, scaled) into the swapchain image or the GL window's framebuffer, and the
// app moves it back to CopySrc for the next frame. No raster pipeline, no host round trip.
//
// Sizes: the image is rendered at --size and scaled to the window, whatever its size; with
// --fit-window the renderer is recreated at the window's framebuffer size on every resize
// (histories restart).
#pragma once

#include <atomic>
#include <memory>
#include <string>

#include "input.hpp"
#include "interactive_scene.hpp"
#include "options.hpp"
#include "renderer/renderer.hpp"
#include "title.hpp"
#include "window_presenter.hpp"

namespace asvgf::demo {

// Validation-layer messages seen so far (counted from any thread; outlives the device).
struct ValidationLog {
  std::atomic<int> messages{0};
};

class App {
 public:
  // The window must be created after set_window_hints(api) (glfwInit done by the caller).
  App(const DemoOptions& options, WindowApi api, GLFWwindow* window, ValidationLog& log);
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  // Runs until Esc, the window closes or --frames frames were shown; returns the exit code.
  int run();

 private:
  void make_renderer(std::uint32_t width, std::uint32_t height);
  void handle_actions();
  void apply_motion(float seconds);
  void resize_hook();
  void visibility_hook();  // the resize storm's minimise/restore and hide/show
  void resize_to(std::uint32_t width, std::uint32_t height);  // and wait (bounded) until the X server did
  hal::ImageHandle shown_image() const;
  void present(hal::ImageHandle image);
  void update_title();
  std::string method_name() const;
  std::string view_name() const;

  DemoOptions options_;
  GLFWwindow* window_;
  std::unique_ptr<hal::Device> device_;
  InteractiveScene scene_;
  render::RenderSettings settings_;
  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<WindowPresenter> presenter_;
  std::unique_ptr<hal::CommandList> to_present_, from_present_;
  Input input_;
  FpsCounter fps_;

  std::size_t view_ = 0;  // index into views()
  int frame_ = 0;         // render frame number: always grows (the Renderer's history logic)
  int still_frames_ = 0;  // frames since something last moved (the reference's accumulation)
  std::optional<scene::FrameState> last_state_;
  std::string title_;
  bool quit_ = false, resized_ = false, screenshot_requested_ = false, hidden_ = false;
  int hides_ = 0, minimised_ = 0;  // by the resize storm
};

}  // namespace asvgf::demo
