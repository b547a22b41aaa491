#include "app.hpp"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "screenshot.hpp"

namespace asvgf::demo {
namespace {

constexpr float kLightSpeed = 0.8f;            // world units per second for held keys (the room is 2 wide)
constexpr float kOrbitPerPixel = 0.005f;       // radians per dragged pixel
constexpr float kDollyPerStep = 0.9f;          // distance factor per wheel step
constexpr int kMaxAtrousIterations = 10;
constexpr std::uint32_t kMinWindowSide = 512;  // small render sizes are scaled up to this

scene::Scene initial_scene(const DemoOptions& o) { return cli::load_scene(o.scene); }

}  // namespace

App::App(const DemoOptions& options, WindowApi api, GLFWwindow* window, ValidationLog& log)
    : options_(options),
      window_(window),
      device_(open_window_device(options.scene.backend, window, options.scene.device, options.scene.validation, log)),
      scene_(initial_scene(options)),
      settings_(cli::render_settings(options.scene)),
      input_(window) {
  view_ = view_index(options.view).value_or(0);
  settings_.spp = options.spp;
  settings_.progressive = true;  // the reference accumulates while nothing moves
  settings_.read_back = false;   // the images stay on the GPU for the presenter
  settings_.debug_view = views()[view_].view;
  if (options.fit_window) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    make_renderer(static_cast<std::uint32_t>(std::max(w, 1)), static_cast<std::uint32_t>(std::max(h, 1)));
  } else {
    make_renderer(settings_.width, settings_.height);
  }
  presenter_ = make_window_presenter(api, *device_, window, !options.no_vsync);
  to_present_ = device_->create_command_list("demo: to present");
  from_present_ = device_->create_command_list("demo: from present");
  std::printf("asvgf-demo: %s on %s (%s), %ux%u, %s; press H for the controls\n", scene_.original().name.c_str(),
              device_->adapter().name.c_str(), renderer_->ray_query() ? "ray queries" : "software BVH",
              settings_.width, settings_.height, method_name().c_str());
  std::fflush(stdout);
}

App::~App() {
  try {
    if (device_) device_->wait();
  } catch (...) {
    // A lost device: the destructors below release what they can.
  }
}

void App::make_renderer(std::uint32_t width, std::uint32_t height) {
  renderer_.reset();  // frees its images first
  settings_.width = width;
  settings_.height = height;
  renderer_ = std::make_unique<render::Renderer>(*device_, scene_.scene(), settings_);
  still_frames_ = -1;  // nothing accumulated yet: the next frame is the first
}

std::string App::method_name() const { return std::string(frame::to_string(settings_.method)); }
std::string App::view_name() const { return views()[view_].name; }

hal::ImageHandle App::shown_image() const {
  return settings_.debug_view ? renderer_->debug_image() : renderer_->display_image();
}

void App::handle_actions() {
  render::RenderSettings next = settings_;
  for (const ActionEvent& e : input_.take_actions()) {
    switch (e.action) {
      case Action::Quit: quit_ = true; break;
      case Action::Pause: scene_.toggle_pause(); break;
      case Action::Restart: scene_.restart(); break;
      case Action::Screenshot: screenshot_requested_ = true; break;
      case Action::Help: std::printf("%s", kControlsHelp); std::fflush(stdout); break;
      case Action::NextView: view_ = (view_ + 1) % views().size(); break;
      case Action::PreviousView: view_ = (view_ + views().size() - 1) % views().size(); break;
      case Action::MoreIterations:
        next.denoise.atrous_iterations = std::min(next.denoise.atrous_iterations + 1, kMaxAtrousIterations);
        break;
      case Action::FewerIterations: next.denoise.atrous_iterations = std::max(next.denoise.atrous_iterations - 1, 0); break;
      case Action::Method: next.method = e.method; break;
    }
  }
  next.debug_view = views()[view_].view;
  // The history tap must name an iteration that runs: the one asked for, or the last one.
  next.denoise.history_tap = std::min(options_.scene.denoise.history_tap, std::max(0, next.denoise.atrous_iterations - 1));
  const bool changed = next.method != settings_.method || next.debug_view != settings_.debug_view ||
                       next.denoise.atrous_iterations != settings_.denoise.atrous_iterations ||
                       next.denoise.history_tap != settings_.denoise.history_tap;
  if (!changed) return;
  if (next.method != settings_.method) still_frames_ = -1;  // the new method starts afresh this frame
  settings_ = next;
  renderer_->set_settings(settings_);
}

void App::apply_motion(float seconds) {
  const Motion m = input_.take_motion();
  const scene::CameraState cam = scene_.camera();
  const glm::vec3 forward = glm::normalize(cam.target - cam.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, cam.up));
  const glm::vec3 up = glm::cross(right, forward);

  if (m.light_keys != glm::vec3(0.0f)) {
    // Left/right along the view, up/down along the world's up, PageUp/PageDown away/towards the
    // camera on the floor plane: the same keys do the same on screen wherever the camera is.
    glm::vec3 flat_forward = forward - glm::normalize(cam.up) * glm::dot(forward, glm::normalize(cam.up));
    if (glm::length(flat_forward) > 1e-4f) flat_forward = glm::normalize(flat_forward);
    const glm::vec3 step =
        right * m.light_keys.x + glm::normalize(cam.up) * m.light_keys.y + flat_forward * m.light_keys.z;
    scene_.move_light(step * kLightSpeed * seconds);
  }
  if (m.light_drag != glm::vec2(0.0f)) {
    // Keep the light under the cursor: one pixel is this many world units at the light's depth.
    int ww = 0, wh = 0;
    glfwGetWindowSize(window_, &ww, &wh);
    const float depth = std::max(0.1f, glm::dot(scene_.light().position - cam.position, forward));
    const float per_pixel =
        2.0f * depth * std::tan(glm::radians(cam.vertical_fov_degrees) * 0.5f) / static_cast<float>(std::max(wh, 1));
    scene_.move_light((right * m.light_drag.x - up * m.light_drag.y) * per_pixel);
  }
  if (m.camera_drag != glm::vec2(0.0f))
    scene_.orbit_camera(-m.camera_drag.x * kOrbitPerPixel, m.camera_drag.y * kOrbitPerPixel);
  if (m.scroll != 0.0f) scene_.dolly(std::pow(kDollyPerStep, m.scroll));
}

void App::resize_hook() {
  if (frame_ < options_.resize_storm) {
    // Four sizes, the next one each frame: every frame presents at a size the last one did not.
    static constexpr std::uint32_t kSizes[4][2] = {{96, 72}, {40, 56}, {128, 32}, {64, 64}};
    resize_to(kSizes[frame_ % 4][0], kSizes[frame_ % 4][1]);
    visibility_hook();
    return;
  }
  if (resized_ || frame_ != options_.resize_frame) return;
  resized_ = true;
  resize_to(options_.resize_to.width, options_.resize_to.height);
}

void App::visibility_hook() {
  if (hidden_) {
    glfwShowWindow(window_);
    hidden_ = false;
  }
  if (frame_ % 10 != 5) return;
  // Every tenth frame of the storm: minimise and restore (without a window manager, as under Xvfb,
  // nothing happens and the summary says so), then hide the window so that this frame presents
  // to an unmapped window; the next frame shows it again.
  auto settle = [&](auto done) {
    for (int tries = 0; tries < 50 && !done(); ++tries) {
      glfwPollEvents();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  };
  glfwIconifyWindow(window_);
  settle([&] { return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE; });
  if (glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE) ++minimised_;
  glfwRestoreWindow(window_);
  settle([&] { return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_FALSE; });
  glfwHideWindow(window_);
  settle([&] { return glfwGetWindowAttrib(window_, GLFW_VISIBLE) == GLFW_FALSE; });
  hidden_ = true;
  ++hides_;
}

void App::resize_to(std::uint32_t w, std::uint32_t h) {
  glfwSetWindowSize(window_, static_cast<int>(w), static_cast<int>(h));
  // The X server applies the size asynchronously: wait (bounded) so the run is reproducible.
  int fw = 0, fh = 0;
  for (int tries = 0; tries < 100; ++tries) {
    glfwPollEvents();
    glfwGetFramebufferSize(window_, &fw, &fh);
    if (static_cast<std::uint32_t>(fw) == w && static_cast<std::uint32_t>(fh) == h) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::printf("asvgf-demo: frame %d: window resized to %ux%u (framebuffer %dx%d)\n", frame_, w, h, fw, fh);
}

void App::present(hal::ImageHandle image) {
  device_->wait();  // last frame's barrier lists are done before they are reset
  to_present_->reset();
  to_present_->barrier({image, hal::State::CopySrc, hal::State::Present});
  device_->submit(*to_present_);
  presenter_->present(image);
  // Back to where the Renderer left it, so that its next frame's graph starts from a known state.
  from_present_->reset();
  from_present_->barrier({image, hal::State::Present, hal::State::CopySrc});
  device_->submit(*from_present_);
}

void App::update_title() {
  TitleInfo info;
  info.method = method_name();
  info.view = view_name();
  info.atrous_iterations = settings_.denoise.atrous_iterations;
  info.fps = fps_.fps();
  info.timings = renderer_->timings();
  info.paused = scene_.paused();
  info.width = settings_.width;
  info.height = settings_.height;
  if (settings_.method == frame::Method::Reference)
    info.note = "accumulated " + std::to_string((still_frames_ + 1) * renderer_->spp_per_frame()) + " spp";
  title_ = format_title(info);
  glfwSetWindowTitle(window_, title_.c_str());
}

int App::run() {
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  const auto start = last;
  hal::ImageHandle shown;
  while (!quit_) {
    glfwPollEvents();
    if (glfwWindowShouldClose(window_)) break;
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    if (fw <= 0 || fh <= 0) {
      glfwWaitEvents();  // minimised: sleep until the window system has news
      last = Clock::now();
      continue;
    }
    resize_hook();
    glfwGetFramebufferSize(window_, &fw, &fh);
    if (options_.fit_window && fw > 0 && fh > 0 &&
        (static_cast<std::uint32_t>(fw) != settings_.width || static_cast<std::uint32_t>(fh) != settings_.height))
      make_renderer(static_cast<std::uint32_t>(fw), static_cast<std::uint32_t>(fh));

    const auto now = Clock::now();
    const float seconds = std::min(0.25f, std::chrono::duration<float>(now - last).count());
    last = now;
    handle_actions();
    if (quit_) break;
    apply_motion(seconds);

    scene_.prepare(frame_);
    const scene::FrameState state = scene::evaluate(scene_.scene(), static_cast<float>(frame_));
    still_frames_ = last_state_ && scene::same_state(*last_state_, state) ? still_frames_ + 1 : 0;
    last_state_ = state;
    renderer_->render(frame_);
    shown = shown_image();
    if (screenshot_requested_) {
      screenshot_requested_ = false;
      const auto path = screenshot_name(options_.screenshot_dir, method_name(), view_name(), frame_);
      save_png(*device_, shown, settings_.width, settings_.height, path);
      std::printf("screenshot: %s\n", path.string().c_str());
      std::fflush(stdout);
    }
    present(shown);
    scene_.advance();
    ++frame_;
    if (fps_.frame() || frame_ == 1) update_title();
    if (options_.frames > 0 && frame_ >= options_.frames) break;
  }
  device_->wait();
  if (!options_.screenshot.empty() && frame_ > 0) {
    save_png(*device_, shown, settings_.width, settings_.height, options_.screenshot);
    std::printf("screenshot: %s (frame %d)\n", options_.screenshot.c_str(), frame_ - 1);
  }
  // The title's rate covers the last half second; a short scripted run reports its own average.
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (fps_.fps() == 0.0 && seconds > 0.0) fps_.set(frame_ / seconds);
  update_title();
  std::string storm;
  if (options_.resize_storm > 0)
    storm = "; presented hidden " + std::to_string(hides_) + " times, minimised " + std::to_string(minimised_) +
            " times (needs a window manager)";
  std::printf("asvgf-demo: %d frames; %s%s; last frame: %s\n", frame_, presenter_->history().c_str(), storm.c_str(),
              title_.c_str());
  return 0;
}

}  // namespace asvgf::demo
