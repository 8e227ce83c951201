// Filling and wall generation of shaped scenes (issue 16: seconds, not minutes, for 10^6 particles in
// 3D): the lattice fill of a sphere, of a box less a cylinder (a tunnel), of a 2D slope, and the wall
// shell of a cylindrical tank, each at about 10^6 lattice points kept. Setup code, timed on one thread.
#include <benchmark/benchmark.h>

#include <cmath>

#include "geometry/lattice_fill.hpp"
#include "geometry/polygon.hpp"

using namespace geosph::geometry;

namespace {

void report(benchmark::State& state, std::size_t kept) {
  state.counters["points"] = static_cast<double>(kept);
  state.counters["points_per_s"] = benchmark::Counter(static_cast<double>(kept), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_FillSphere(benchmark::State& state) {  // 4/3 pi (0.5 / dx)^3 = 1.05e6 points at dx = 0.008
  const auto s = make_ball(3, {0.5, 0.5, 0.5}, 0.5);
  std::size_t n = 0;
  for (auto _ : state) n = fill_lattice(*s, 0.008).size();
  report(state, n);
}

void BM_FillTunnel(benchmark::State& state) {  // a 1 m cube less a bore of radius 0.25 m: 0.8 m^3 at dx = 0.0093
  const auto s = make_difference(3, {make_box(3, {0, 0, 0}, {1, 1, 1}), make_cylinder({0.5, 0.5, 0.5}, 0, 0.25, 1.2)});
  std::size_t n = 0;
  for (auto _ : state) n = fill_lattice(*s, 0.0093).size();
  report(state, n);
}

void BM_FillSlope2D(benchmark::State& state) {  // 30 m x 10 m less the air above a 2:1 slope: 250 m^2 at dx = 0.0158
  const auto s = make_difference(2, {make_box(2, {0, 0, 0}, {30, 10, 0}),
                                     make_polygon({{10, 10}, {20, 5}, {30, 5}, {30, 10.5}, {10, 10.5}}, {})});
  std::size_t n = 0;
  for (auto _ : state) n = fill_lattice(*s, 0.0158).size();
  report(state, n);
}

void BM_WallShellCylinder(benchmark::State& state) {  // three layers of a 2 m tank's shell at dx = 0.005
  const auto s = make_difference(3, {make_cylinder({0, 0, 1.0}, 2, 0.515, 2.03), make_cylinder({0, 0, 1.5}, 2, 0.5, 3.0)});
  std::size_t n = 0;
  for (auto _ : state) n = fill_lattice(*s, 0.005, 0.015).size();
  report(state, n);
}

}  // namespace

BENCHMARK(BM_FillSphere)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FillTunnel)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FillSlope2D)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WallShellCylinder)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
