// A progress line on stderr for long runs: redrawn in place on a terminal, one line per step
// otherwise (logs), nothing when quiet.
#pragma once

#include <unistd.h>
#include <chrono>
#include <cstdio>
#include <string>

namespace asvgf::cli {

class Progress {
 public:
  Progress(std::string what, int total, bool quiet)
      : what_(std::move(what)),
        total_(total),
        quiet_(quiet),
        tty_(isatty(fileno(stderr)) != 0),
        start_(std::chrono::steady_clock::now()) {}

  void step(int done, const std::string& note = {}) {
    if (quiet_) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const int width = 30;
    const int filled = total_ > 0 ? done * width / total_ : width;
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "%s%s [%s] %d/%d  %.1f s%s%s", tty_ ? "\r" : "", what_.c_str(), bar.c_str(), done, total_,
                 elapsed, note.empty() ? "" : "  ", note.c_str());
    std::fprintf(stderr, tty_ && done < total_ ? "" : "\n");
    std::fflush(stderr);
  }

 private:
  std::string what_;
  int total_;
  bool quiet_, tty_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace asvgf::cli
