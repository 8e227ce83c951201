// Throughput of the time loop on catalogue scenes: material particle-steps per second of
// wall-clock time at three sizes and 1 or 2 OpenMP threads, for
//   DamBreak2D         the 2D dam break (fluid; ~10k, ~40k, ~160k particles)
//   GranularCollapse2D the aluminium-bar column collapse (Drucker-Prager soil; ~5k, ~20k, ~80k)
//   GranularCollapseCamClay2D the same column as Modified Cam Clay (implicit return; same sizes)
//   TwoPhaseConsolidation2D the Terzaghi layer: pore water + soil skeleton (coupling/seepage) in the same
//                      space, N water and N skeleton particles (~2 x 5k, 2 x 20k, 2 x 80k material)
//
// Each scene is the catalogue one with only dx changed, so that its first body (the water column,
// the soil column) holds about N particles: dx = sqrt(body area / N). Building the Simulation (particles, cell
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
#include <vector>

#include "io/scene.hpp"
#include "sim/simulation.hpp"

namespace {

constexpr int kWarmupSteps = 5;

std::filesystem::path data_dir() {
  if (const char* env = std::getenv("GEOSPH_DATA_DIR")) return env;
  return GEOSPH_DEFAULT_DATA_DIR;
}

geosph::Scene sized_scene(const std::string& case_name, long target_particles) {
  geosph::Scene scene = geosph::load_scene(data_dir() / "verification" / "cases" / case_name / "scene.json");
  const auto& body = scene.bodies.front();
  const double area = (body.hi[0] - body.lo[0]) * (body.hi[1] - body.lo[1]);
  scene.dx = std::sqrt(area / static_cast<double>(target_particles));
  geosph::validate_scene(scene);
  return scene;
}

// range(0): target particle count; range(1): OpenMP threads.
void BM_Scene(benchmark::State& state, const std::string& case_name) {
  const long target = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);

  geosph::Simulation sim(sized_scene(case_name, target));
  for (int s = 0; s < kWarmupSteps; ++s) sim.step();

  for (auto _ : state) {
    sim.step();
    benchmark::ClobberMemory();
  }

  const double material = static_cast<double>(sim.moving_count());
  const double total = static_cast<double>(sim.particles().size());
  state.counters["material"] = material;
  state.counters["total"] = total;  // material + wall particles
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(material * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  // Wall-clock time per fluid particle-step (printed with an SI prefix, e.g. 1.1us), to compare
  // sizes: constant if the cost is O(N). The wall particles (~27% extra at 10k, ~7% at 160k) are
  // not counted as particle-steps but their work (wall extrapolation, neighbour search) is timed.
  state.counters["time_per_particle_step"] =
      benchmark::Counter(material * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Fixed step counts, so the whole run takes about a minute on a 2-core machine (~8e6 fluid
// particle-steps per case, roughly the same work at every size).
void register_all() {
  struct Size { long n; long steps; };
  struct Case { const char* name; const char* scene; std::vector<Size> sizes; };
  const std::vector<Case> cases = {
      {"DamBreak2D/step", "dam_break_2d", {{10'000, 800}, {40'000, 200}, {160'000, 50}}},
      {"GranularCollapse2D/step", "granular_collapse_bui", {{5'000, 800}, {20'000, 200}, {80'000, 50}}},
      {"GranularCollapseCamClay2D/step", "granular_collapse_cam_clay", {{5'000, 800}, {20'000, 200}, {80'000, 50}}},
      {"TwoPhaseConsolidation2D/step", "terzaghi_consolidation", {{5'000, 400}, {20'000, 100}, {80'000, 25}}}};
  for (const auto& c : cases)
  for (const Size sz : c.sizes)
    for (const long threads : {1L, 2L})
      benchmark::RegisterBenchmark(c.name, BM_Scene, std::string(c.scene))
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
