#include "sim/progress.hpp"

#include <unistd.h>

#include <algorithm>

namespace geosph {

Progress::Progress(double t_end, bool enabled)
    : t_end_(t_end), enabled_(enabled), tty_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void Progress::update(long step, double t) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double frac = std::clamp(t / t_end_, 0.0, 1.0);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = frac > 0 ? elapsed * (1.0 - frac) / frac : 0.0;
  if (tty_) {
    if (std::chrono::duration<double>(now - last_draw_).count() < 0.2) return;
    last_draw_ = now;
    const int width = 30, filled = static_cast<int>(frac * width);
    std::fprintf(stderr, "\r[");
    for (int k = 0; k < width; ++k) std::fputc(k < filled ? '#' : '.', stderr);
    std::fprintf(stderr, "] %5.1f%%  step %ld  t = %.4g s  ETA %.0f s   ", 100 * frac, step, t, eta);
    std::fflush(stderr);
  } else {
    const int decile = static_cast<int>(frac * 10);
    if (decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(stderr, "progress %3d%%  step %ld  t = %.4g s  elapsed %.1f s  ETA %.0f s\n", decile * 10, step, t,
                 elapsed, eta);
  }
}

void Progress::finish(long step, double t) {
  if (!enabled_) return;
  if (tty_) std::fprintf(stderr, "\n");
  (void)step; (void)t;
}

}  // namespace geosph
