// Strain-driven element (material-point) tests of the soil models: triaxial compression paths
// driven through the solver's own point model, shared by the unit tests and the catalogue.
// Compression positive in the outputs (soil mechanics convention), axial direction x.
#pragma once
#include <vector>

#include "soil/modified_cam_clay.hpp"

namespace geosph::verify {

struct TriaxialPath {
  // one entry per output (every out_every of axial strain): compression positive
  std::vector<double> eps_a, p, q, eps_v;
  std::vector<char> plastic;
  bool converged = true;            // every return converged
  int max_iterations = 0;           // of the return mapping
  int plastic_steps = 0;
  double max_lateral_residual = 0;  // drained: max |sigma_r - sigma_r0| / p'_0
  double max_slope_dev = 0;         // drained: max |q - 3 (p' - p'_0)| / q
};

// Drained conventional triaxial compression from the isotropic state p'_0 (p_c = OCR p'_0): axial
// strain steps d; the lateral strain of each step is solved (Newton, finite-difference slope) so
// that the lateral stress stays at -p'_0.
TriaxialPath mcc_drained_triaxial_run(const soil::ModifiedCamClay& model, double p0, double ocr, double d,
                                      double eps_end, double out_every);
// Undrained (isochoric) triaxial compression: d eps = diag(-d, d/2, d/2).
TriaxialPath mcc_undrained_triaxial_run(const soil::ModifiedCamClay& model, double p0, double ocr, double d,
                                        double eps_end, double out_every);

}  // namespace geosph::verify
