// demo/input.hpp: keyboard and mouse through GLFW callbacks, turned into the demo's actions
// (discrete key presses, queued) and motions (light and camera moves, gathered per frame).
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/frame_graph.hpp"

struct GLFWwindow;

namespace asvgf::demo {

enum class Action { Quit, Pause, Restart, Screenshot, Help, NextView, PreviousView, MoreIterations, FewerIterations, Method };

struct ActionEvent {
  Action action;
  frame::Method method = frame::Method::Asvgf;  // for Action::Method
};

// What moved since the last frame.
struct Motion {
  glm::vec3 light_keys{0.0f};      // held keys: x right/left, y up/down, z away/towards, unit per second
  glm::vec2 light_drag{0.0f};      // left-button drag, window pixels (x right, y down)
  glm::vec2 camera_drag{0.0f};     // right-button drag, window pixels
  float scroll = 0.0f;             // wheel steps, positive: towards the target
};

class Input {
 public:
  // Installs the callbacks (the window's user pointer is this object; it must outlive them).
  explicit Input(GLFWwindow* window);
  ~Input();
  Input(const Input&) = delete;
  Input& operator=(const Input&) = delete;

  // Key presses since the last call, in order.
  std::vector<ActionEvent> take_actions();
  // Drags, wheel and held keys since the last call.
  Motion take_motion();

 private:
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void on_button(GLFWwindow* window, int button, int action, int mods);
  static void on_cursor(GLFWwindow* window, double x, double y);
  static void on_scroll(GLFWwindow* window, double dx, double dy);

  GLFWwindow* window_;
  std::vector<ActionEvent> actions_;
  Motion motion_;
  std::optional<glm::dvec2> cursor_;
  bool left_ = false, right_ = false;
};

}  // namespace asvgf::demo
