#include "sim/resource_limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "boundary/geometry.hpp"

namespace geosph {

namespace {

// Lattice points of [lo, hi) at spacing dx (boundary/geometry.cpp's lattice), in double: no overflow.
double lattice_count(int dim, const std::array<double, 3>& lo, const std::array<double, 3>& hi, double dx) {
  double n = 1;
  for (int a = 0; a < dim; ++a) n *= std::max(0.0, std::round((hi[a] - lo[a]) / dx));
  return n;
}

// Memory available to this process [bytes], or 0 when unknown.
double available_memory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024.0;
  return 0;
}

std::string human(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

ResourceEstimate estimate_resources(const Scene& s) {
  ResourceEstimate e;
  for (const auto& b : s.bodies) e.particles += lattice_count(s.dim, b.lo, b.hi, s.dx);
  const double L = wall_layers(s) * s.dx;
  for (const auto& c : s.walls.containers) {
    auto lo = c.lo, hi = c.hi;
    for (int a = 0; a < s.dim; ++a) { lo[a] -= L; hi[a] += L; }
    e.particles += lattice_count(s.dim, lo, hi, s.dx) - lattice_count(s.dim, c.lo, c.hi, s.dx);
  }
  for (const auto& b : s.walls.blocks) e.particles += lattice_count(s.dim, b.lo, b.hi, s.dx);
  // Bytes per particle: peak resident memory over particle count of catalogue scenes refined to
  // 1.3-6.4 x 10^5 particles (dam_break_2d 0.28 kB, granular_collapse_bui 0.50 kB, the two sets of
  // terzaghi_consolidation 0.60 kB), with a margin for output buffers and the physics' scratch.
  const double per = s.two_phase() ? 1000 : s.has_soil() ? 700 : 350;
  // the Verlet pair list (core/cell_list.hpp): 5 bytes a pair (index and periodic image) for the
  // lattice neighbours within the support plus skin (twice as many where two phases share the space),
  // and the positions at its build
  const double reach = (1.0 + s.pair_list_skin) * s.support() / s.dx;
  const double pairs = (s.dim == 2 ? std::numbers::pi * reach * reach : 4.0 / 3.0 * std::numbers::pi * reach * reach * reach) *
                       (s.two_phase() ? 2.0 : 1.0);
  e.bytes = e.particles * (per + (s.pair_list_skin > 0 ? 5.0 * pairs + 24.0 : 0.0));
  const double cell = s.support() / 2;  // CellList: cells half the support wide
  e.cells = 1;
  for (int a = 0; a < s.dim; ++a) e.cells *= std::max(1.0, std::floor(s.domain.length(a) / cell));
  return e;
}

void check_resources(const Scene& s) {
  const ResourceEstimate e = estimate_resources(s);
  const auto fail = [&](const std::string& field, const std::string& what) {
    throw InputError(s.file + ": field '" + field + "': " + what);
  };
  std::ostringstream dx;
  dx << s.dx;
  if (e.particles > s.limits.max_particles)
    fail("dx", "dx = " + dx.str() + " m creates about " + human(e.particles) + " particles, more than the limit of " +
                   human(s.limits.max_particles) + " (about " + human(e.bytes / 1e9) +
                   " GB); raise it with --max-particles if this is intended");
  const double avail = available_memory();
  if (avail > 0 && e.bytes > avail)
    fail("dx", "dx = " + dx.str() + " m creates about " + human(e.particles) + " particles, needing about " +
                   human(e.bytes / 1e9) + " GB, more than the " + human(avail / 1e9) + " GB this machine has available");
  if (e.cells > s.limits.max_cells)
    fail("domain", "the domain spans about " + human(e.cells) + " neighbour-search cells (half a kernel support, " +
                       std::to_string(s.support() / 2) + " m, wide), more than the limit of " + human(s.limits.max_cells) +
                       "; make the domain fit the region the particles can reach, or raise --max-cells");
  if (avail > 0 && 8.0 * e.cells > avail)
    fail("domain", "the domain's " + human(e.cells) + " neighbour-search cells need more memory than this machine has");
}

}  // namespace geosph
