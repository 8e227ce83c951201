#include "structure/rigid_motion.hpp"

#include "boundary/body_fields.hpp"

#include <cmath>
#include <stdexcept>
#include "core/time_step.hpp"

namespace geosph {

namespace {
// f(i, body b, its motion) for every rigid structure particle
template <class F>
void for_each_rigid(Particles& P, const Scene& scene, F&& f) {
  const std::int32_t* body = P.int_field(BodyFields::structure_body).data();
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::RigidStructure) continue;
    const auto b = static_cast<std::size_t>(body[i]) - 1;
    f(i, b, scene.bodies[b].motion);
  }
}
}  // namespace

RigidMotions::RigidMotions(const Scene& scene) : scene_(scene), state_(scene.bodies.size()) {
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) state_[b].centre = scene.bodies[b].motion.centre;
}

void RigidMotions::set_velocities(Particles& P, double t) const {
  for_each_rigid(P, scene_, [&](std::size_t i, std::size_t b, const BodySpec::Motion& m) {
    const double f = smooth_start(t, m.ramp);
    const auto& c = state_[b].centre;
    P.vx[i] = f * (m.velocity[0] - m.angular_velocity * (P.y[i] - c[1]));
    P.vy[i] = f * (m.velocity[1] + m.angular_velocity * (P.x[i] - c[0]));
    P.vz[i] = f * m.velocity[2];
  });
}

void RigidMotions::advance(Particles& P, double t, double dt) {
  for_each_rigid(P, scene_, [&](std::size_t i, std::size_t b, const BodySpec::Motion& m) {
    const double f = smooth_start(t + 0.5 * dt, m.ramp);
    const double th = f * m.angular_velocity * dt;
    const auto& c = state_[b].centre;
    const double rx = P.x[i] - c[0], ry = P.y[i] - c[1];
    P.x[i] = c[0] + std::cos(th) * rx - std::sin(th) * ry + f * m.velocity[0] * dt;
    P.y[i] = c[1] + std::sin(th) * rx + std::cos(th) * ry + f * m.velocity[1] * dt;
    P.z[i] += f * m.velocity[2] * dt;
  });
  for (std::size_t b = 0; b < scene_.bodies.size(); ++b) {
    const auto& m = scene_.bodies[b].motion;
    if (!scene_.bodies[b].is_rigid_structure()) continue;
    const double f = smooth_start(t + 0.5 * dt, m.ramp);
    for (int a = 0; a < 3; ++a) {
      state_[b].centre[a] += f * m.velocity[a] * dt;
      state_[b].displacement[a] += f * m.velocity[a] * dt;
    }
    state_[b].angle += f * m.angular_velocity * dt;
  }
  set_velocities(P, t + dt);
}

std::vector<double> RigidMotions::state() const {
  std::vector<double> v;
  for (const auto& s : state_) {
    v.insert(v.end(), s.centre.begin(), s.centre.end());
    v.insert(v.end(), s.displacement.begin(), s.displacement.end());
    v.push_back(s.angle);
  }
  return v;
}

void RigidMotions::restore_state(const std::vector<double>& v) {
  if (v.size() != 7 * state_.size()) throw std::invalid_argument("rigid motion state: wrong size");
  for (std::size_t b = 0; b < state_.size(); ++b) {
    const double* q = v.data() + 7 * b;
    for (int a = 0; a < 3; ++a) { state_[b].centre[a] = q[a]; state_[b].displacement[a] = q[3 + a]; }
    state_[b].angle = q[6];
  }
}

}  // namespace geosph
