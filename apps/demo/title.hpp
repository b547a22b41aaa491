// demo/title.hpp: the window title as the demo's overlay: method, buffer shown, a-trous
// iterations, frames per second, per-pass GPU milliseconds (the costliest few and the total) and
// the keys.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "asvgf/graph_runtime.hpp"

namespace asvgf::demo {

struct TitleInfo {
  std::string method, view;
  int atrous_iterations = 0;
  double fps = 0.0;
  std::vector<PassTime> timings;
  bool paused = false;
  std::uint32_t width = 0, height = 0;  // render size
  std::string note;                     // e.g. "accumulating 37 frames"
};

// Passes with the same name prefix before a '.' ("atrous.1".."atrous.5") are summed into one.
std::string format_title(const TitleInfo& info, std::size_t top_passes = 3);

// Frames per second over a sliding half second.
class FpsCounter {
 public:
  // Counts a frame; returns true when the rate was updated.
  bool frame();
  double fps() const { return fps_; }
  void set(double fps) { fps_ = fps; }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_ = Clock::now();
  int frames_ = 0;
  double fps_ = 0.0;
};

}  // namespace asvgf::demo
