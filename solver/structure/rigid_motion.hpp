// Prescribed rigid motion of structure bodies (a retaining wall translated or rotated at a set rate).
// Each rigid body has a reference point c(t) moving with f(t) V and turns about it with f(t) omega
// (2D, about z), f(t) = smooth_start(t, ramp) (core/time_step.hpp, the same ramp as gravity's). Positions advance exactly for the step's rotation:
//   x <- c + R(f omega dt) (x - c) + f V dt,   c <- c + f V dt   (f at mid-step),
// and the velocity v = f (V + omega e_z x (x - c)) is what the contact sees.
#pragma once
#include <array>
#include <vector>

#include "core/particles.hpp"
#include "io/scene.hpp"

namespace geosph {

class RigidMotions {
 public:
  explicit RigidMotions(const Scene& scene);
  // Moves every Kind::RigidStructure particle from t to t + dt and sets its velocity at t + dt.
  void advance(Particles& P, double t, double dt);
  // Sets the velocities at time t (start of the run).
  void set_velocities(Particles& P, double t) const;

  // Accumulated translation of body b's reference point and its rotation [rad] so far.
  std::array<double, 3> displacement(std::size_t body) const { return state_[body].displacement; }
  double rotation(std::size_t body) const { return state_[body].angle; }
  // The running state (centre, displacement, angle of every body) as numbers, for a checkpoint.
  std::vector<double> state() const;
  void restore_state(const std::vector<double>& v);

 private:
  struct State {
    std::array<double, 3> centre{}, displacement{};
    double angle = 0;
  };
  const Scene& scene_;
  std::vector<State> state_;  // per scene body (unused for non-rigid bodies)
};

}  // namespace geosph
