// A start relaxed against mirror walls (boundary/mirror_wall.hpp). A Cartesian lattice is mirror-
// symmetric only about the lattice's own planes: next to an inclined or curved surface its points lie
// at any distance in [0, dx) and those nearer than dx/2 crowd their own images, so a lattice start
// against mirror walls is not in equilibrium (a still tank sloshes). Before t = 0 the particles of each
// shaped fluid body are moved to a uniform arrangement inside the body's own surface, which is the
// wall where the body meets one: particle packing by the gradient of the kernel sum (Zhu, Zhang &
// Adams 2021, Comput. Phys. Commun. 258, 107585, Sec. 2.2: x_i += -beta h^2 sum_j V_j grad W_ij,
// the neighbours with their images across the body's surface as mirror walls make them, so that the
// surface rows settle half a spacing from it). Then the density and pressure of the body's initial
// state are set again at the new positions. Setup code: runs once in build_particles.
#pragma once
#include <cstddef>

#include "core/particles.hpp"
#include "io/scene.hpp"

namespace geosph {

struct RelaxationResult {
  int iterations = 0;
  // h |sum_j V_j grad W_ij| (0 on a full lattice): the largest over the body's particles (an acute
  // corner, which two mirror planes do not fill, keeps it) and the mean
  double initial_residual = 0, final_residual = 0, initial_mean = 0, final_mean = 0;
};

// Relaxes the particles [first, first + count) of body b (a fluid body with a shape) in P.
RelaxationResult relax_body_against_mirror_walls(const Scene& s, const BodySpec& b, Particles& P, std::size_t first,
                                                 std::size_t count);

}  // namespace geosph
