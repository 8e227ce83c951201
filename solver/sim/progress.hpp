// Run progress: a bar on a terminal (step, simulated time, ETA), plain log lines otherwise.
#pragma once
#include <chrono>
#include <cstdio>

namespace geosph {

class Progress {
 public:
  Progress(double t_end, bool enabled);
  void update(long step, double t);
  void finish(long step, double t);

 private:
  double t_end_;
  bool enabled_, tty_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace geosph
