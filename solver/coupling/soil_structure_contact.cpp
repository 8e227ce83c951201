#include "coupling/soil_structure_contact.hpp"

#include "boundary/body_fields.hpp"

#include <cmath>
#include <numbers>

namespace geosph {

SoilStructureContact::SoilStructureContact(const Scene& scene) : scene_(scene) {
  for (const auto& b : scene.bodies)
    tan_delta_.push_back(b.structure ? std::tan(std::max(0.0, b.interface_friction_angle) * std::numbers::pi / 180.0)
                                     : 0.0);
}

void SoilStructureContact::allocate(Particles& P) const {
  for (const char* f : {ContactFields::fx, ContactFields::fy, ContactFields::fz, ContactFields::nx, ContactFields::ny,
                        ContactFields::nz})
    P.add_field(f, "soil_structure_contact");
}

template <class K>
void SoilStructureContact::normals_with(const K& kernel, Particles& P, const CellList& cells) const {
  const std::int32_t* body = P.int_field(BodyFields::structure_body).data();
  double* nx = P.field(ContactFields::nx).data();
  double* ny = P.field(ContactFields::ny).data();
  double* nz = P.field(ContactFields::nz).data();
  const double threshold = 1e-3 / scene_.h();
  const std::size_t n = P.size();
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t j = 0; j < n; ++j) {
    if (!is_structure(P.kind[j])) continue;
    double g[3] = {0, 0, 0};
    cells.for_each_neighbor(P, j, [&](std::uint32_t k, double dx, double dy, double dz, double r2) {
      if (!is_structure(P.kind[k]) || body[k] != body[j]) return;
      const double f = P.m[k] / P.rho[k] * kernel.gradW_over_r(std::sqrt(r2));
      g[0] += f * dx; g[1] += f * dy; g[2] += f * dz;
    });
    const double norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const double s = norm > threshold ? -1.0 / norm : 0.0;
    nx[j] = s * g[0]; ny[j] = s * g[1]; nz[j] = s * g[2];
  }
}

void SoilStructureContact::apply(Particles& P, const CellList& cells, double dt) const {
  std::visit([&](const auto& k) { normals_with(k, P, cells); }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
  const std::size_t n = P.size();
  const std::int32_t* body = P.int_field(BodyFields::structure_body).data();
  const double* nx = P.field(ContactFields::nx).data();
  const double* ny = P.field(ContactFields::ny).data();
  const double* nz = P.field(ContactFields::nz).data();
  const std::int32_t* fixed = P.find_int(BodyFields::fixed);
  // a structure particle that the contact force moves: deformable, not held by a clamp
  const auto free_structure = [&](std::size_t j) { return P.kind[j] == Kind::Structure && !(fixed && fixed[j] > 0); };
  const double dx0 = scene_.dx;
  partner_.assign(n, -1);
  force_.resize(n);
  shift_.assign(n, {0.0, 0.0, 0.0});
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    long best = -1;
    double best_r2 = 1e300;
    cells.for_each_neighbor(P, i, [&](std::uint32_t j, double, double, double, double r2) {
      if (!is_structure(P.kind[j]) || (nx[j] == 0 && ny[j] == 0 && nz[j] == 0)) return;
      if (r2 < best_r2) { best_r2 = r2; best = j; }
    });
    if (best < 0) continue;
    const auto j = static_cast<std::size_t>(best);
    const double nrm[3] = {nx[j], ny[j], nz[j]};
    const double d[3] = {P.x[i] - P.x[j], P.y[i] - P.y[j], P.z[i] - P.z[j]};
    // a penetration is at most the centres' overlap dx - |d|: a soil particle one spacing from a convex
    // corner particle (diagonal normal) touches it, and is not pushed off the corner
    const double gap = std::max(d[0] * nrm[0] + d[1] * nrm[1] + d[2] * nrm[2] - dx0,
                                std::min(0.0, std::sqrt(best_r2) - dx0));
    if (gap > 0.5 * dx0) continue;
    // a penetration is pushed out by position, a fraction of it each step, not by a velocity: the soil
    // particle is moved along the normal (see the header), after the loop, since the neighbour queries
    // of other soil particles read its position
    if (gap < 0 && !(fixed && fixed[i] > 0)) {
      const double s = -kPenetrationRecovery * gap;
      shift_[i] = {s * nrm[0], s * nrm[1], s * nrm[2]};
    }
    const bool rigid = !free_structure(j);  // prescribed motion (its velocity) or clamped (held at rest)
    double vj[3] = {P.vx[j], P.vy[j], P.vz[j]};
    if (!rigid) { vj[0] += dt * P.ax[j]; vj[1] += dt * P.ay[j]; vj[2] += dt * P.az[j]; }
    const double u[3] = {P.vx[i] + dt * P.ax[i] - vj[0], P.vy[i] + dt * P.ay[i] - vj[1], P.vz[i] + dt * P.az[i] - vj[2]};
    const double un = u[0] * nrm[0] + u[1] * nrm[1] + u[2] * nrm[2];
    const double target = gap >= 0 ? -gap / dt : 0.0;  // closes the gap in the step; a penetration no further
    if (un >= target) continue;
    const double mred = rigid ? P.m[i] : P.m[i] * P.m[j] / (P.m[i] + P.m[j]);
    const double Fn = mred * (target - un) / dt;
    const double ut[3] = {u[0] - un * nrm[0], u[1] - un * nrm[1], u[2] - un * nrm[2]};
    const double ut_norm = std::sqrt(ut[0] * ut[0] + ut[1] * ut[1] + ut[2] * ut[2]);
    const double Ft_stick = mred * ut_norm / dt;
    const double Ft = std::min(Ft_stick, tan_delta_[static_cast<std::size_t>(body[j]) - 1] * Fn);
    const double st = ut_norm > 0 ? -Ft / ut_norm : 0.0;
    const std::array<double, 3> F = {Fn * nrm[0] + st * ut[0], Fn * nrm[1] + st * ut[1], Fn * nrm[2] + st * ut[2]};
    P.ax[i] += F[0] / P.m[i]; P.ay[i] += F[1] / P.m[i]; P.az[i] += F[2] / P.m[i];
    partner_[i] = best;
    force_[i] = F;
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    P.x[i] += shift_[i][0]; P.y[i] += shift_[i][1]; P.z[i] += shift_[i][2];
  }
  // reactions (serial: several soil particles may press on one structure particle)
  double* fx = P.field(ContactFields::fx).data();
  double* fy = P.field(ContactFields::fy).data();
  double* fz = P.field(ContactFields::fz).data();
  for (std::size_t j = 0; j < n; ++j)
    if (is_structure(P.kind[j])) fx[j] = fy[j] = fz[j] = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (partner_[i] < 0) continue;
    const auto j = static_cast<std::size_t>(partner_[i]);
    const auto& F = force_[i];
    fx[j] -= F[0]; fy[j] -= F[1]; fz[j] -= F[2];
    if (free_structure(j)) {
      P.ax[j] -= F[0] / P.m[j]; P.ay[j] -= F[1] / P.m[j]; P.az[j] -= F[2] / P.m[j];
    }
  }
}

std::array<double, 3> SoilStructureContact::body_force(const Particles& P, std::size_t body) {
  std::array<double, 3> F{0, 0, 0};
  if (!P.has_field(ContactFields::fx)) return F;
  const auto& b = P.int_field(BodyFields::structure_body);
  const auto& fx = P.field(ContactFields::fx);
  const auto& fy = P.field(ContactFields::fy);
  const auto& fz = P.field(ContactFields::fz);
  for (std::size_t j = 0; j < P.size(); ++j)
    if (static_cast<std::size_t>(b[j]) == body + 1) { F[0] += fx[j]; F[1] += fy[j]; F[2] += fz[j]; }
  return F;
}

}  // namespace geosph
