// Slope stability by shear strength reduction (Zienkiewicz, Humpheson & Lewis 1975, Geotechnique 25(4)
// 671-689; Griffiths & Lane 1999, Geotechnique 49(3) 387-403; in SPH: Bui, Fukagawa, Sako & Wells 2011,
// Geotechnique 61(7) 565-574). A trial factor F divides the cohesion and tan(phi) of every
// Drucker-Prager and Mohr-Coulomb material (the dilatancy angle is capped at the reduced friction angle);
// the scene's gravity-loading stage then loads the slope from rest. A trial has failed when
//   (a) its kinetic energy does not fall to gravity_loading.kinetic_energy_ratio of its peak within
//       gravity_loading.max_time (the damped slope keeps moving: no equilibrium), or
//   (b) the displacement exceeded by 5% of the soil particles (u95) passes `displacement_limit` (a
//       mechanism: a sliding mass of at least 5% of the soil moves that far), or
//   (c) the run becomes unstable (InstabilityError).
// F is bisected between the largest stable and the smallest failed trial to `tolerance`; the factor of
// safety is the mid-point of the final bracket. The failure surface is the base of the moving mass of
// the failed trial nearest F as it ended (slip_surface); its plastic-strain band is kept with it.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/particles.hpp"

namespace geosph {

struct StrengthReductionOptions {
  double f_low = 0.8, f_high = 2.0;  // the bracket: f_low must be stable and f_high fail (both run first)
  double tolerance = 0.01;           // bisection stops when f_high - f_low <= tolerance
  double displacement_limit = 0.5;   // m: criterion (b)
};

struct StrengthReductionTrial {
  double factor = 0;
  bool stable = false;
  std::string reason;               // why it counts as stable or failed
  double time = 0;                  // s of loading simulated
  long steps = 0;
  double displacement = 0;          // u95 at the trial's end [m]
  double kinetic_energy_ratio = 0;  // at the trial's end, of its peak
};

struct StrengthReductionResult {
  double factor_of_safety = 0;      // mid-point of [f_stable, f_failed]
  double f_stable = 0, f_failed = 0;
  std::vector<StrengthReductionTrial> trials;  // in the order run
  std::vector<std::array<double, 2>> failure_surface;  // 2D: x, y of the slip surface (slip_surface)
  std::vector<std::array<double, 2>> plastic_band;     // 2D: x, y of the plastic-strain band (plastic_band)
  Particles failed_state;           // the failed trial nearest F, as it ended
};

// The scene with c/F, atan(tan(phi)/F) and min(psi, phi_F) for every drucker_prager and mohr_coulomb
// material (F > 0).
nlohmann::json reduce_strength(const nlohmann::json& scene, double factor);

// `report` sees every trial as it ends, with its particles. Throws InputError naming the option if f_low fails or f_high holds (the factor is outside the
// bracket), or the scene has no gravity_loading stage or no material to reduce.
StrengthReductionResult strength_reduction(const nlohmann::json& scene, const std::string& file,
                                           const StrengthReductionOptions& options,
                                           const std::function<void(const StrengthReductionTrial&, const Particles&)>& report = {});

// The band of plastic strain (2D): in each column of width 2 dx, the position of the soil particle of
// largest equivalent plastic strain, where that strain is at least `fraction` of the largest in the
// soil; columns in x order.
std::vector<std::array<double, 2>> plastic_band(const Particles& P, double dx, double fraction = 0.3);

// The slip surface of a moving slope (2D): in each column of width 2 dx whose fastest soil particle
// moves at least `fraction` of the fastest in the soil, the height below which the soil moves at less
// than half that column's fastest speed (mid-way between the two particles where the speed crosses
// it); columns in x order. The moving mass slides on this line (the velocity field of the
// not-converged SSR trial: Griffiths & Lane 1999, Fig. 6, show its displacement vectors).
std::vector<std::array<double, 2>> slip_surface(const Particles& P, double dx, double fraction = 0.3);

}  // namespace geosph
