// Steady confined seepage under a single sheet pile (2D, isotropic homogeneous layer).
//
// Thin pile (zero thickness), embedment s in a layer of thickness T on an impermeable base, total head H
// on the upstream ground surface and 0 downstream, laterally infinite: the conformal-mapping solution
// (Harr 1962, "Groundwater and Seepage", McGraw-Hill, Ch. 5; the forms below as derived and checked in
// shared/reference-data/sheet_pile_seepage_analytical_finite_depth.csv, evaluated here independently
// with GSL's elliptic integrals). With k = sin(pi s / 2T), k' = sqrt(1 - k^2), K the complete elliptic
// integral of the first kind and F the incomplete one:
//   discharge                     q / (k_perm H) = K(k') / (2 K(k))
//   exit gradient (downstream)    i(x) = pi H / (2 sqrt(2) T K(k) sqrt(cosh(pi x / T) - cos(pi s / T)))
//   at the pile face              i_E = pi H / (4 T k K(k))               (-> H / (pi s) as T -> inf)
//   head at the toe               h_toe = H / 2                            (antisymmetry, any T)
//   downstream face, depth d      h / H = F(phi, k) / (2 K(k)),  sin(phi) = sin(pi d / 2T) / k
//
// Thick pile (the pile an SPH wall block of thickness t must be): no closed form, so the same boundary
// value problem is solved by a cell-centred finite-volume Laplace solver (5-point stencil, Dirichlet
// heads on the two ground surfaces, no flow through the base, the side walls and the pile faces; Eigen's
// sparse Cholesky). It solves exactly the geometry of the SPH scene (side walls at x = -W and W); at
// t = 0 on a wide domain it reproduces the closed forms above (verification/unit/
// test_analytical_references.cpp).
#pragma once
#include <vector>

namespace geosph::reference {

// Closed forms for a thin pile; s_over_T in (0, 1).
struct ThinSheetPile {
  double s_over_T;
  double discharge_over_kH() const;
  double exit_gradient_at_face_times_T_over_H() const;
  // head / H on the downstream face at depth d / T in [0, s / T]
  double downstream_face_head(double depth_over_T) const;
  // exit gradient * T / H on the downstream ground surface at x / T >= 0 from the pile
  double exit_gradient_times_T_over_H(double x_over_T) const;
};

// Geometry of the finite-volume problem, in metres: layer -T < y < 0, side walls x = -W and x = W, the
// pile occupying -t/2 < x < t/2 from y = -s up through the ground surface. grid is the cell size; T, W,
// s and t/2 must be whole multiples of it.
struct SheetPileGeometry {
  double T, W, s, t, grid;
};

class SheetPileLaplace {
 public:
  // Solves for the head with H = 1 upstream and 0 downstream.
  explicit SheetPileLaplace(const SheetPileGeometry& g);
  // head / H at (x, y) in the soil, bilinear between cell centres (nearest cell value at the edges;
  // inside the pile, the nearest soil cell on the point's side)
  double head(double x, double y) const;
  // discharge per unit width / (k H): the flow through the downstream ground surface
  double discharge_over_kH() const { return q_; }
  const SheetPileGeometry& geometry() const { return g_; }

 private:
  SheetPileGeometry g_;
  int nx_, ny_;
  std::vector<double> h_;    // by cell, row-major from the bottom-left; NaN inside the pile
  double q_ = 0;
  bool in_pile(int i, int j) const;
  double cell(int i, int j) const { return h_[static_cast<std::size_t>(j) * nx_ + i]; }
};

}  // namespace geosph::reference
