#include "input.hpp"

#include <GLFW/glfw3.h>

#include <utility>

namespace asvgf::demo {
namespace {

Input& self(GLFWwindow* window) { return *static_cast<Input*>(glfwGetWindowUserPointer(window)); }

}  // namespace

Input::Input(GLFWwindow* window) : window_(window) {
  glfwSetWindowUserPointer(window, this);
  glfwSetKeyCallback(window, on_key);
  glfwSetMouseButtonCallback(window, on_button);
  glfwSetCursorPosCallback(window, on_cursor);
  glfwSetScrollCallback(window, on_scroll);
}

Input::~Input() {
  glfwSetKeyCallback(window_, nullptr);
  glfwSetMouseButtonCallback(window_, nullptr);
  glfwSetCursorPosCallback(window_, nullptr);
  glfwSetScrollCallback(window_, nullptr);
  glfwSetWindowUserPointer(window_, nullptr);
}

std::vector<ActionEvent> Input::take_actions() { return std::exchange(actions_, {}); }

Motion Input::take_motion() {
  Motion m = std::exchange(motion_, {});
  // Held keys are read now rather than from events, so that a held key moves the light smoothly
  // whatever the key-repeat rate.
  auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0f : 0.0f; };
  m.light_keys = {held(GLFW_KEY_RIGHT) - held(GLFW_KEY_LEFT), held(GLFW_KEY_UP) - held(GLFW_KEY_DOWN),
                  held(GLFW_KEY_PAGE_UP) - held(GLFW_KEY_PAGE_DOWN)};
  return m;
}

void Input::on_key(GLFWwindow* window, int key, int, int action, int mods) {
  if (action != GLFW_PRESS) return;
  auto& in = self(window);
  auto push = [&](Action a) { in.actions_.push_back({a}); };
  switch (key) {
    case GLFW_KEY_ESCAPE: push(Action::Quit); break;
    case GLFW_KEY_SPACE: push(Action::Pause); break;
    case GLFW_KEY_R: push(Action::Restart); break;
    case GLFW_KEY_P: push(Action::Screenshot); break;
    case GLFW_KEY_H: push(Action::Help); break;
    case GLFW_KEY_V: push((mods & GLFW_MOD_SHIFT) ? Action::PreviousView : Action::NextView); break;
    // '+' is Shift+'=' on most layouts: take both, and the keypad's.
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD: push(Action::MoreIterations); break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: push(Action::FewerIterations); break;
    default:
      if (key >= GLFW_KEY_1 && key <= GLFW_KEY_5)
        in.actions_.push_back({Action::Method, frame::kAllMethods[key - GLFW_KEY_1]});
      break;
  }
}

void Input::on_button(GLFWwindow* window, int button, int action, int) {
  auto& in = self(window);
  const bool down = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_LEFT) in.left_ = down;
  if (button == GLFW_MOUSE_BUTTON_RIGHT) in.right_ = down;
}

void Input::on_cursor(GLFWwindow* window, double x, double y) {
  auto& in = self(window);
  const glm::dvec2 now(x, y);
  if (in.cursor_) {
    const glm::vec2 delta(now - *in.cursor_);
    if (in.left_) in.motion_.light_drag += delta;
    if (in.right_) in.motion_.camera_drag += delta;
  }
  in.cursor_ = now;
}

void Input::on_scroll(GLFWwindow* window, double, double dy) { self(window).motion_.scroll += static_cast<float>(dy); }

}  // namespace asvgf::demo
