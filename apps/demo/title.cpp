#include "title.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

namespace asvgf::demo {

std::string format_title(const TitleInfo& info, std::size_t top_passes) {
  char buf[256];
  std::string t = "asvgf-demo | " + info.method + " | view " + info.view;
  std::snprintf(buf, sizeof buf, " | a-trous %d | %ux%u | %.1f fps", info.atrous_iterations, info.width, info.height,
                info.fps);
  t += buf;
  if (info.paused) t += " | paused";
  if (!info.note.empty()) t += " | " + info.note;

  std::map<std::string, double> groups;
  bool timed = !info.timings.empty();
  for (const auto& p : info.timings) {
    if (!p.gpu_ms) timed = false;
    groups[p.pass.substr(0, p.pass.find('.'))] += p.gpu_ms.value_or(0.0);
  }
  if (timed) {
    std::vector<std::pair<std::string, double>> sorted(groups.begin(), groups.end());
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    double total = 0.0;
    for (const auto& g : sorted) total += g.second;
    std::snprintf(buf, sizeof buf, " | GPU %.2f ms:", total);
    t += buf;
    for (std::size_t i = 0; i < std::min(top_passes, sorted.size()); ++i) {
      std::snprintf(buf, sizeof buf, " %s %.2f", sorted[i].first.c_str(), sorted[i].second);
      t += buf;
    }
  } else {
    t += " | GPU times n/a";
  }
  t += " | keys: arrows/PgUp/PgDn/LMB light, RMB camera, 1-5 method, V view, +/- a-trous, space pause, P shot, H help, "
       "Esc quit";
  return t;
}

bool FpsCounter::frame() {
  ++frames_;
  const auto now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  if (seconds < 0.5) return false;
  fps_ = frames_ / seconds;
  frames_ = 0;
  start_ = now;
  return true;
}

}  // namespace asvgf::demo
