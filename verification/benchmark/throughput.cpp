// Throughput of the time loop on the 2D dam break (verification/cases/dam_break_2d/scene.json):
// fluid particle-steps per second of wall-clock time, at ~10k, ~40k and ~160k fluid particles and
// 1 or 2 OpenMP threads.
//
// The scene is the catalogue one with only dx changed, so that the 0.146 m x 0.292 m water column
// holds about N particles: dx = sqrt(0.146 * 0.292 / N). Building the Simulation (particles, cell
// list, first force evaluation) and a few warm-up steps are outside the timed region; each timed
// iteration is one Simulation::step() (neighbour search, continuity, pressure, wall extrapolation,
// momentum, state check, time-step choice, plus the reorder every scene.reorder_every steps).
//
// The data directory is GEOSPH_DATA_DIR from the environment if set, else the build-time default.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/scene.hpp"
#include "sim/simulation.hpp"

namespace {

constexpr double kColumnWidth = 0.146, kColumnHeight = 0.292;  // the water body in scene.json [m]
constexpr int kWarmupSteps = 5;

std::filesystem::path data_dir() {
  if (const char* env = std::getenv("GEOSPH_DATA_DIR")) return env;
  return GEOSPH_DEFAULT_DATA_DIR;
}

geosph::Scene dam_break_scene(long target_fluid_particles) {
  geosph::Scene scene = geosph::load_scene(data_dir() / "verification" / "cases" / "dam_break_2d" / "scene.json");
  scene.dx = std::sqrt(kColumnWidth * kColumnHeight / static_cast<double>(target_fluid_particles));
  geosph::validate_scene(scene);
  return scene;
}

// range(0): target fluid particle count; range(1): OpenMP threads.
void BM_DamBreak2D(benchmark::State& state) {
  const long target = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);

  geosph::Simulation sim(dam_break_scene(target));
  for (int s = 0; s < kWarmupSteps; ++s) sim.step();

  for (auto _ : state) {
    sim.step();
    benchmark::ClobberMemory();
  }

  const double fluid = static_cast<double>(sim.fluid_count());
  const double total = static_cast<double>(sim.particles().size());
  state.counters["fluid"] = fluid;
  state.counters["total"] = total;  // fluid + dummy wall particles
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(fluid * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  // Wall-clock time per fluid particle-step (printed with an SI prefix, e.g. 1.1us), to compare
  // sizes: constant if the cost is O(N). The wall particles (~27% extra at 10k, ~7% at 160k) are
  // not counted as particle-steps but their work (wall extrapolation, neighbour search) is timed.
  state.counters["time_per_particle_step"] =
      benchmark::Counter(fluid * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Fixed step counts, so the whole run takes about a minute on a 2-core machine (~8e6 fluid
// particle-steps per case, roughly the same work at every size).
void register_all() {
  struct Size { long n; long steps; };
  for (const Size sz : {Size{10'000, 800}, Size{40'000, 200}, Size{160'000, 50}})
    for (const long threads : {1L, 2L})
      benchmark::RegisterBenchmark("DamBreak2D/step", BM_DamBreak2D)
          ->Args({sz.n, threads})
          ->ArgNames({"N", "threads"})
          ->Iterations(sz.steps)
          ->UseRealTime()
          ->MeasureProcessCPUTime()  // CPU column = all threads; CPU/Time ~ threads when the machine is quiet
          ->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
