// Throughput of the time loop on catalogue scenes: material particle-steps per second of
// wall-clock time at three sizes and 1 or 2 OpenMP threads, for
//   DamBreak2D         the 2D dam break (fluid; ~10k, ~40k, ~160k particles)
//   GranularCollapse2D the aluminium-bar column collapse (Drucker-Prager soil; ~5k, ~20k, ~80k)
//   GranularCollapseCamClay2D the same column as Modified Cam Clay (implicit return; same sizes)
//   TwoPhaseConsolidation2D the Terzaghi layer: pore water + soil skeleton (coupling/seepage) in the same
//                      space, N water and N skeleton particles (~2 x 5k, 2 x 20k, 2 x 80k material)
// and, only when asked for (--benchmark_filter=Scaling), the cost's growth with N from 10^4 to 10^6
// particles: Scaling/DamBreak2D (the catalogue dam break) and Scaling/DamBreak3D (a 3D dam break,
// scaling/dam_break_3d.json), a few steps each: constant time_per_particle_step means O(N).
//
// Each scene is the catalogue one with only dx changed, so that its first body (the water column,
// the soil column) holds about N particles: dx = (body area or volume / N)^(1/dim). Building the Simulation (particles, cell
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

// `scene_file`: relative to the data directory.
geosph::Scene sized_scene(const std::string& scene_file, long target_particles) {
  geosph::Scene scene = geosph::load_scene(data_dir() / scene_file);
  const auto& body = scene.bodies.front();
  double size = 1;
  for (int a = 0; a < scene.dim; ++a) size *= body.hi[a] - body.lo[a];
  scene.dx = std::pow(size / static_cast<double>(target_particles), 1.0 / scene.dim);
  geosph::validate_scene(scene);
  return scene;
}

// range(0): target particle count; range(1): OpenMP threads.
void BM_Scene(benchmark::State& state, const std::string& scene_file) {
  const long target = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);

  geosph::Simulation sim(sized_scene(scene_file, target));
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
  struct Case { const char* name; std::string scene; std::vector<Size> sizes; };
  const auto catalogue = [](const char* name) { return std::string("verification/cases/") + name + "/scene.json"; };
  const std::vector<Case> cases = {
      {"DamBreak2D/step", catalogue("dam_break_2d"), {{10'000, 800}, {40'000, 200}, {160'000, 50}}},
      {"GranularCollapse2D/step", catalogue("granular_collapse_bui"), {{5'000, 800}, {20'000, 200}, {80'000, 50}}},
      {"GranularCollapseCamClay2D/step", catalogue("granular_collapse_cam_clay"), {{5'000, 800}, {20'000, 200}, {80'000, 50}}},
      {"TwoPhaseConsolidation2D/step", catalogue("terzaghi_consolidation"), {{5'000, 400}, {20'000, 100}, {80'000, 25}}},
      // multiples of reorder_every (20) steps: every size has the same share of reorders (each one
      // rebuilds the pair list)
      {"Scaling/DamBreak2D/step", catalogue("dam_break_2d"), {{10'000, 400}, {100'000, 40}, {1'000'000, 20}}},
      {"Scaling/DamBreak3D/step", "verification/benchmark/scaling/dam_break_3d.json",
       {{10'000, 200}, {100'000, 40}, {1'000'000, 20}}}};
  for (const auto& c : cases)
  for (const Size sz : c.sizes)
    for (const long threads : {1L, 2L})
      benchmark::RegisterBenchmark(c.name, BM_Scene, c.scene)
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
  benchmark::SetBenchmarkFilter("-Scaling");  // the default set; --benchmark_filter replaces it
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
