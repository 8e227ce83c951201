// The gravity-loading stage: the standard geotechnical start for sloping ground. Before t = 0 the
// scene's solids are loaded by their weight (optionally ramped) and settle under local non-viscous
// damping, a_c -= alpha |a_c| sign(v_c) per component (Cundall 1987, "Distinct element models of rock
// and soil structure", in Analytical and Computational Methods in Engineering Rock Mechanics, ch. 4;
// the "local damping" of Itasca's FLAC), until their kinetic energy has fallen below a fraction of its
// peak. With "elastic" the solids are linear elastic during the stage (their own E and nu), so the
// stage finds the elastic equilibrium stress; with "material" they follow their own model. Then the
// velocities are zeroed, time restarts at 0, and the run proper begins from the settled state.
#pragma once
#include <array>
#include <string>

#include "core/particles.hpp"
#include "io/json_fields.hpp"
#include "io/scene.hpp"

namespace geosph {


// gravity_loading (a top-level section; GravityLoadingSpec in io/scene.hpp).
GravityLoadingSpec parse_gravity_loading(const JsonFields& f);

// What the stage did, for the run's log and records.
struct GravityLoadingResult {
  bool ran = false;
  bool settled = true;  // false: max_time passed, or the monitor abandoned the stage (try_settle_under_gravity)
  long steps = 0;
  double time = 0, peak_kinetic_energy = 0, final_kinetic_energy = 0;
  double final_force_ratio = 0;  // the unbalanced-force ratio at the end (unbalanced_force_ratio)
};

// Cundall's local damping on the solid particles' accelerations (moving solids only).
void apply_local_damping(Particles& P, double alpha);
// The solids' mean unbalanced force over their mean weight, sum_i m_i |a_i| / sum_i m_i |g|, a_i the
// undamped acceleration (gravity, the contact and every other force included) of the moving solid particles (a fixed part carries a
// reaction): the equilibrium ratio of FLAC (Itasca), zero only at equilibrium. The kinetic energy alone
// also vanishes at every turning point of an oscillation: a column stopped there by the energy criterion
// kept its first mode, sigma_v 3% low (nu = 0.2) to 5% high (nu = 0.4) (issue 17, item 3).
double unbalanced_force_ratio(const Particles& P, const std::array<double, 3>& g);
// Kinetic energy of the solid particles (soil and structures).
double solid_kinetic_energy(const Particles& P);

}  // namespace geosph
