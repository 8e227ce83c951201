// The mirror walls' share of the fluid rates (boundary/mirror_wall.hpp): for each fluid particle i near
// a wall, the continuity, delta-SPH, pressure and viscous terms of fluid_forces.hpp with the images
// j' = T(x_j) of the fluid particles j within the support of T(x_i), for each image map T of i.
// The image carries m_j, the velocity R v_j (free slip) or -v_j (no slip), the pressure
// p_j + rho_j g . (x_j' - x_j) and its density from the equation of state. Viscous terms act with the
// images whatever the slip: a free-slip image has the tangential velocity of its particle, so only the
// approaching normal velocity is damped (the artificial viscosity's wall repulsion) and a laminar
// viscosity sees no wall shear.
#include <cmath>

#include "fluid/fluid_forces.hpp"

namespace geosph {

void FluidForces::add_mirror_images(Particles& P, const CellList& cells, const std::array<double, 3>& g) const {
  std::visit([&](const auto& k) {
    if (scene_.dim == 2) mirror_images_with<2>(k, P, cells, g);
    else mirror_images_with<3>(k, P, cells, g);
  }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

template <int Dim, class K>
void FluidForces::mirror_images_with(const K& kernel, Particles& P, const CellList& cells, const std::array<double, 3>& g) const {
  const std::size_t n = P.size();
  const double h = scene_.h(), eta2 = 0.01 * h * h, eta2_lam = 1e-4 * h * h;  // as rates_with
  const Kind* kind = P.kind.data();
  double* drho_out = drho_new_.data();
  const auto dot = [](const double* a, const double* b) {
    return Dim == 3 ? a[0] * b[0] + a[1] * b[1] + a[2] * b[2] : a[0] * b[0] + a[1] * b[1];
  };
#pragma omp parallel
  {
  MirrorSet set;
  const std::vector<MirrorImage>& images = set.images;
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (kind[i] != Kind::Fluid) continue;
    const double xi[3] = {P.x[i], P.y[i], Dim == 3 ? P.z[i] : 0.0};
    mirror_->images(xi, set);
    if (images.empty()) continue;
    const FluidMaterial& mi = mats_[P.material[i]];
    const TaitEos& eos_i = eos_[P.material[i]];
    const double rhoi = P.rho[i], pi_r2 = P.p[i] / (rhoi * rhoi);
    const double vi[3] = {P.vx[i], P.vy[i], Dim == 3 ? P.vz[i] : 0.0};
    const double av_i = mi.artificial_viscosity * mi.sound_speed * h;
    const double mu_i = rhoi * mi.kinematic_viscosity;
    const double delta_hc = mi.density_diffusion * h * mi.sound_speed;
    double drho = 0, acc[3] = {0, 0, 0};
    for (const MirrorImage& T : images) {
      const auto q = T.apply(xi);  // T(x_i): j' is within the support of x_i where j is within that of q
      cells.for_each_near_point(P, q[0], q[1], q[2], [&](std::uint32_t j, double dx, double dy, double dz, double r2) {
        if (kind[j] != Kind::Fluid) return;
        const double d[3] = {dx, dy, dz};  // q - x_j
        const auto r = T.rotate(d);         // x_i - x_j' = R (T(x_i) - x_j)
        const double xj_image[3] = {xi[0] - r[0], xi[1] - r[1], xi[2] - r[2]};
        if (!set.keep(T, xj_image)) return;
        const double step[3] = {xj_image[0] - (q[0] - dx), xj_image[1] - (q[1] - dy), xj_image[2] - (q[2] - dz)};
        const TaitEos& eos_j = eos_[P.material[j]];
        const double pj = P.p[j] + P.rho[j] * dot(g.data(), step);  // the hydrostatic step across the wall
        const double rhoj = eos_j.density(pj), mj = P.m[j];
        const double vj[3] = {P.vx[j], P.vy[j], Dim == 3 ? P.vz[j] : 0.0};
        std::array<double, 3> vimg = T.rotate(vj);
        if (!T.free_slip) vimg = {-vj[0], -vj[1], -vj[2]};
        const double u[3] = {vi[0] - vimg[0], vi[1] - vimg[1], vi[2] - vimg[2]};
        const double fw = kernel.gradW_over_r(std::sqrt(r2));
        const double inv_r2 = 1.0 / (r2 + eta2);
        const double ur = dot(u, r.data());
        drho += mj * fw * ur;  // continuity (Monaghan 1992, eq. 4.7)
        if (delta_hc > 0) {    // delta-SPH (Molteni & Colagrossi 2009), hydrostatic part removed as in rates_with
          double dr = rhoi - rhoj;
          if (mi.density_diffusion_hydrostatic) dr -= eos_i.hydrostatic_density_difference(dot(g.data(), r.data()));
          drho += delta_hc * 2.0 * dr * fw * r2 * inv_r2 * mj / rhoj;
        }
        double coef = mj * (pi_r2 + pj / (rhoj * rhoj));
        coef += -mj * av_i * std::min(ur, 0.0) * inv_r2 * 2.0 / (rhoi + rhoj);  // Monaghan 1992, eq. 4.2
        if (mu_i > 0) {  // Morris et al. 1997, eq. 10, the image with i's viscosity
          const double lam = mj * 2.0 * mu_i * (fw * r2) / (rhoi * rhoj * (r2 + eta2_lam));
          for (int a = 0; a < Dim; ++a) acc[a] += lam * u[a];
        }
        for (int a = 0; a < Dim; ++a) acc[a] -= coef * fw * r[a];
      });
    }
    drho_out[i] += drho;
    P.ax[i] += acc[0];
    P.ay[i] += acc[1];
    if constexpr (Dim == 3) P.az[i] += acc[2];
  }
  }
}

}  // namespace geosph
