// Builds the initial particle set of a scene: fluid bodies on a Cartesian lattice of spacing dx
// (particle centres at min + (i + 1/2) dx) and wall containers as `layers` lattice layers outside
// the container's inner faces, so that fluid and wall lattices line up.
#pragma once
#include <vector>

#include "boundary/mirror_relaxation.hpp"
#include "core/particles.hpp"
#include "io/scene.hpp"

namespace geosph {

// What a body was filled with: its particle count and mass, and its material density times its area
// (2D) or volume (3D), which the lattice fill approaches as dx shrinks.
struct BodyFill {
  std::size_t particles = 0;
  double mass = 0, shape_mass = 0;
  RelaxationResult relaxation;  // a shaped fluid body against mirror walls (boundary/mirror_relaxation.hpp)
};

// With fills, one entry per body (scene order). A body placed during the run (placed_at > 0) is not in
// the returned set: it is built on its own into `placed` (one set per such body, scene order).
Particles build_particles(const Scene& scene, std::vector<BodyFill>* fills = nullptr,
                          std::vector<Particles>* placed = nullptr);
int wall_layers(const Scene& scene);
// The initial density of fluid body b's particle at (x, y, z): rho0 at rest, or the Tait hydrostatic
// state below the body's highest point ("hydrostatic").
double fluid_initial_density(const Scene& s, const BodySpec& b, double x, double y, double z);

}  // namespace geosph
