// Builds the initial particle set of a scene: fluid bodies on a Cartesian lattice of spacing dx
// (particle centres at min + (i + 1/2) dx) and wall containers as `layers` lattice layers outside
// the container's inner faces, so that fluid and wall lattices line up.
#pragma once
#include "core/particles.hpp"
#include "io/scene.hpp"

namespace geosph {

Particles build_particles(const Scene& scene);
int wall_layers(const Scene& scene);

}  // namespace geosph
