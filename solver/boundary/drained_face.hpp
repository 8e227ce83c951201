// Drained faces of a container (walls.containers[k].drained): the pore water of saturated soil leaves
// through them at a prescribed pressure, while the skeleton rests on them as on any wall. A drained
// face is the filter or porous stone under a consolidating layer (single or double drainage; Terzaghi
// 1943, ch. XIII), written as a boundary condition instead of a layer of free water.
// For the pore water a drained wall particle w carries
//   p_w = p_d + rho_w g . (x_w - x_f)    (x_f: w's foot on the face; hydrostatic behind the face)
// with the porosity of its water neighbours (the dummy walls' average), enters the pressure gradient
// only (Dirichlet), and is left out of the water's continuity and viscosity: the water crosses the face
// with its own velocity (zero normal gradient). A water particle that has crossed the face is removed
// (Simulation::drain); the removed mass is the drained water.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/particles.hpp"
#include "io/scene.hpp"

namespace geosph {

struct DrainedFace {
  std::size_t container = 0;  // walls.containers index
  int axis = 0;            // the face's normal axis
  bool upper = false;      // the container's upper face on that axis (the wall lies above it)
  double plane = 0;        // the face's coordinate on `axis`
  std::array<double, 3> lo{}, hi{};  // the container's inner box (the face's tangential extent)
  double pressure = 0;     // p_d [Pa] at the face
  // depth of x behind the face (> 0 beyond it, on the wall's side)
  double depth(const double x[3]) const { return upper ? x[axis] - plane : plane - x[axis]; }
  // The face's hydrostatic line at x: p_d + rho g . (x - x_f), x_f the foot of x on the face.
  double hydrostatic_pressure(const double x[3], double rho, const std::array<double, 3>& g) const {
    return pressure + rho * depth(x) * (upper ? g[axis] : -g[axis]);
  }
  // x lies within the face's tangential extent (its own axis not checked)
  bool spans(const double x[3], int dim) const {
    for (int a = 0; a < dim; ++a)
      if (a != axis && (x[a] < lo[a] || x[a] > hi[a])) return false;
    return true;
  }
};

struct DrainedFields {
  static constexpr const char* owner = "geometry";
  static constexpr const char* face = "wall_drained";  // int: index + 1 into drained_faces(scene) (0: not drained)
};

// Every drained face of the scene's containers, in container order then side order (the index that
// wall_drained holds).
std::vector<DrainedFace> drained_faces(const Scene& scene);

// Index + 1 of the drained face that the wall lattice point x of container c lies behind (0: none). A
// point behind two faces (an edge or corner of the container) is not drained.
std::int32_t drained_face_of(const Scene& scene, const std::vector<DrainedFace>& faces, std::size_t container,
                             const double x[3]);

// The water particles (Kind::Fluid) that have crossed a drained face within its extent.
std::vector<char> crossed_drained_faces(const Scene& scene, const std::vector<DrainedFace>& faces, const Particles& P);

}  // namespace geosph
