// Filling and wall generation of shaped scenes (issue 16: seconds, not minutes, for 10^6 particles in
// 3D): the lattice fill of a sphere, of a box less a cylinder (a tunnel), of a 2D slope, of an STL
// sphere, and the wall shells of a cylindrical tank and of the STL sphere. Setup code, timed on one thread.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "geometry/lattice_fill.hpp"
#include "geometry/polygon.hpp"
#include "geometry/stl_mesh.hpp"

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

// A UV sphere of radius 0.5 as an STL (128 x 64 quads, 16k triangles), written once.
std::filesystem::path stl_sphere() {
  const auto path = std::filesystem::temp_directory_path() / "geosph_bench_sphere.stl";
  std::ofstream o(path);
  o << "solid s\n";
  const int nu = 128, nv = 64;
  auto P = [&](int i, int j) {
    if (j == 0 || j == nv) return std::array<double, 3>{0.5, 0.5, j == 0 ? 1.0 : 0.0};  // the poles
    const double th = M_PI * j / nv, ph = 2 * M_PI * i / nu;
    return std::array<double, 3>{0.5 + 0.5 * std::sin(th) * std::cos(ph), 0.5 + 0.5 * std::sin(th) * std::sin(ph),
                                 0.5 + 0.5 * std::cos(th)};
  };
  auto tri = [&](std::array<double, 3> a, std::array<double, 3> b, std::array<double, 3> c) {
    o << "facet normal 0 0 0\nouter loop\n";
    for (const auto& v : {a, b, c}) o << "vertex " << v[0] << " " << v[1] << " " << v[2] << "\n";
    o << "endloop\nendfacet\n";
  };
  o.precision(17);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int i1 = (i + 1) % nu;  // the seam shares its vertices
      const auto a = P(i, j), b = P(i1, j), c = P(i1, j + 1), d = P(i, j + 1);
      if (j > 0) tri(a, c, b);
      if (j < nv - 1) tri(a, d, c);
    }
  o << "endsolid s\n";
  return path;
}

// The STL sphere filled at dx = 0.008 (1e6 points): the CGAL side-of-mesh test per lattice point.
void BM_FillStlSphere(benchmark::State& state) {
  const auto s = make_stl(stl_sphere());
  std::size_t n = 0;
  for (auto _ : state) n = fill_lattice(*s, 0.008).size();
  report(state, n);
}

// Three wall layers inside the STL sphere at dx = 0.004 (0.56e6 points kept): the side test and the
// AABB distance near the surface, the deep inside skipped by blocks (geometry/lattice_fill.cpp).
void BM_WallShellStlSphere(benchmark::State& state) {
  const auto s = make_stl(stl_sphere());
  std::size_t n = 0;
  for (auto _ : state) n = fill_lattice(*s, 0.004, 0.012).size();
  report(state, n);
}

}  // namespace

BENCHMARK(BM_FillStlSphere)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FillSphere)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FillTunnel)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FillSlope2D)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WallShellCylinder)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WallShellStlSphere)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
