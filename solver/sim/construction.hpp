// Construction and excavation stages: the way an engineer excavates in front of a wall or raises an
// embankment. An excavation (top-level "excavations") removes, at its time, the soil and fluid
// particles inside its shape; a body with "placed_at" appears at that time, at rest with its initial
// state. With gravity_loading.after_construction the solids then settle again under local damping at
// the held time (Simulation::settle_after_construction), as a staged analysis solves each stage to
// equilibrium before the next (e.g. Potts & Zdravkovic 2001, Finite Element Analysis in Geotechnical
// Engineering: Theory, sec. 12.2-12.3, for excavation and construction).
#pragma once
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "io/json_fields.hpp"
#include "io/scene.hpp"

namespace geosph {

// excavations[k] (ExcavationSpec in io/scene.hpp).
ExcavationSpec parse_excavation(const JsonFields& f, int dim);

// What one construction event did, for the run's log.
struct ConstructionEvent {
  std::string what;        // "excavations[k]" or "bodies[k]"
  double time = 0;         // scene time of the event [s]
  std::size_t removed = 0, added = 0;  // particles
  long settle_steps = 0;   // steps of the damped settling after it (0: none)
  bool settled = true;     // false: the kinetic energy did not fall to the ratio in max_time
};

// Flags the soil and fluid particles inside `shape` (contains(p, dx), the fill's own test), to remove.
std::vector<char> inside_excavation(const Particles& P, const geometry::Shape& shape, double dx);

// The first particle of `P` closer than dx/2 to a particle of `added` (the placed body would sit on
// it), or -1.
long first_overlap(const Particles& P, const Particles& added, double dx);

}  // namespace geosph
