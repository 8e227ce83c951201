// The Poiseuille start-up series (Morris et al. 1997, eq. 21): limits and symmetry.
#include <gtest/gtest.h>

#include <gsl/gsl_integration.h>

#include <cmath>
#include <string>
#include <vector>

#include "analytical/poiseuille.hpp"
#include "analytical/sheet_pile_seepage.hpp"
#include "analytical/terzaghi_consolidation.hpp"
#include "harness/case_config.hpp"
#include "harness/metrics.hpp"

using geosph::reference::PoiseuilleStartup;

TEST(PoiseuilleStartup, StartsAtRestAndReachesTheParabola) {
  const PoiseuilleStartup p{2e-4, 1e-6, 1e-3};
  for (double y : {0.1e-3, 0.5e-3, 0.77e-3}) {
    EXPECT_NEAR(p.velocity(y, 0.0), 0.0, 1e-6 * p.max_velocity());
    const double steady = p.F / (2 * p.nu) * y * (p.L - y);
    EXPECT_NEAR(p.velocity(y, 100.0), steady, 1e-9 * p.max_velocity());
  }
  EXPECT_NEAR(p.velocity(0.5e-3, 100.0), p.max_velocity(), 1e-12);
}

TEST(PoiseuilleStartup, SymmetricAndZeroAtThePlates) {
  const PoiseuilleStartup p{2e-4, 1e-6, 1e-3};
  for (double t : {0.01, 0.1, 0.5}) {
    EXPECT_NEAR(p.velocity(0.0, t), 0.0, 1e-12);
    EXPECT_NEAR(p.velocity(p.L, t), 0.0, 1e-12);
    EXPECT_NEAR(p.velocity(0.2e-3, t), p.velocity(0.8e-3, t), 1e-12);
    EXPECT_LT(p.velocity(0.5e-3, t), p.velocity(0.5e-3, t + 0.05));  // accelerates monotonically
  }
}

// Terzaghi consolidation (reference/analytical/terzaghi_consolidation): a step load on incompressible
// water gives the classical average degree of consolidation U(T) = 1 - sum 2/M^2 exp(-M^2 T); U = 50%
// at T = 0.197 and 90% at T = 0.848 (Terzaghi 1943, "Theoretical Soil Mechanics"; the same values in
// Craig's Soil Mechanics, the table of U against T_v), and U = sqrt(4T/pi) at early T (the layer as a
// half-space; the first image term, 4 sqrt(T) ierfc(1/sqrt(T)), is below 1e-10 for T <= 0.05). A short ramp lands on the step solution once the ramp is far behind.
TEST(Terzaghi, StepLoadDegreeOfConsolidation) {
  using namespace geosph::reference;
  const TerzaghiSpec s = terzaghi_spec(2.0, 1e-6, 9810.0, 1e7, 0.4, 0.0, 1000.0, 0.0);
  EXPECT_DOUBLE_EQ(s.B, 1.0);
  const double tT = s.height * s.height / s.cv;  // time per unit T
  EXPECT_NEAR(terzaghi_degree_of_consolidation(s, 0.197 * tT), 0.50, 1e-3);
  EXPECT_NEAR(terzaghi_degree_of_consolidation(s, 0.848 * tT), 0.90, 1e-3);
  for (double T : {0.01, 0.03, 0.05})
    EXPECT_NEAR(terzaghi_degree_of_consolidation(s, T * tT), std::sqrt(4.0 * T / M_PI), 1e-6) << "T = " << T;
  // pore pressure: B q at once below a thin boundary layer, zero at the drained top, and the base value
  // u(H)/q = sum 2/M sin(M) exp(-M^2 T) = 0.5 at T = 0.379 (the median of the base's dissipation)
  EXPECT_NEAR(terzaghi_excess_pressure(s, 1.0, 1e-4 * tT), 1000.0, 1e-6);
  EXPECT_NEAR(terzaghi_excess_pressure(s, 0.0, 0.3 * tT), 0.0, 1e-9);
  double u_base = 0;
  for (int m = 0; m < 50; ++m) {
    const double M = M_PI * (2 * m + 1) / 2;
    u_base += 2 / M * std::sin(M) * std::exp(-M * M * 0.379);
  }
  EXPECT_NEAR(terzaghi_excess_pressure(s, 2.0, 0.379 * tT) / 1000.0, u_base, 1e-9);
  EXPECT_NEAR(u_base, 0.5, 2e-3);
  // compressible water: c_v = k / (gamma_w (m_v + n/K_w)), B = m_v / (m_v + n/K_w)
  const TerzaghiSpec c = terzaghi_spec(1.0, 1e-2, 9810.0, 2.5e5, 0.4, 2.5e6, 1250.0, 0.2);
  EXPECT_NEAR(c.B, 4e-6 / (4e-6 + 1.6e-7), 1e-12);
  EXPECT_NEAR(c.cv, 1e-2 / (9810.0 * 4.16e-6), 1e-9);
  // ramped load, long after the ramp: the step solution shifted by about half the ramp
  const TerzaghiSpec step = terzaghi_spec(1.0, 1e-2, 9810.0, 2.5e5, 0.4, 2.5e6, 1250.0, 0.0);
  EXPECT_NEAR(terzaghi_mean_excess_pressure(c, 1.0), terzaghi_mean_excess_pressure(step, 0.9), 2e-3 * 1250.0);
  EXPECT_NEAR(terzaghi_load(c, 0.1), 625.0, 1e-9);
  EXPECT_THROW(terzaghi_spec(1.0, -1e-2, 9810.0, 2.5e5, 0.4, 2.5e6, 1250.0, 0.2), std::invalid_argument);
  EXPECT_THROW(terzaghi_excess_pressure(c, 1.5, 0.3), std::invalid_argument);
}

// The ramped load's modes in closed form against Duhamel's integral of the step response taken by GSL
// quadrature: u_ramp(z, t) = int_0^min(t, t_r) q'(tau)/q0 u_step(z, t - tau) dtau, q' of the cosine ramp,
// during the ramp and after it, at the base and mid-depth, for a slow and a fast ramp (T_r = 0.049 and
// 4.9e-4: the second needs 1e5-1e6 modes during the ramp, where the series converges as 1/M^2).
TEST(Terzaghi, RampedLoadIsDuhamelsIntegralOfTheStep) {
  using namespace geosph::reference;
  for (double tr : {0.2, 0.002}) {
    const TerzaghiSpec r = terzaghi_spec(1.0, 1e-2, 9810.0, 2.5e5, 0.4, 2.5e6, 1250.0, tr);
    const TerzaghiSpec st = terzaghi_spec(1.0, 1e-2, 9810.0, 2.5e5, 0.4, 2.5e6, 1250.0, 0.0);
    for (double t : {0.5 * tr, tr, 3 * tr, 0.6})
      for (double z : {1.0, 0.5}) {
        struct P { const TerzaghiSpec* st; double t, z, tr; } p{&st, t, z, tr};
        gsl_function f{[](double tau, void* v) {
                         const auto* q = static_cast<P*>(v);
                         const double rate = 0.5 * M_PI / q->tr * std::sin(M_PI * tau / q->tr);
                         return q->t - tau <= 0 ? rate * q->st->B * q->st->load
                                                : rate * terzaghi_excess_pressure(*q->st, q->z, q->t - tau);
                       },
                       &p};
        gsl_integration_workspace* w = gsl_integration_workspace_alloc(200);
        double duhamel = 0, err = 0;
        gsl_integration_qag(&f, 0.0, std::min(t, tr), 1e-12, 1e-10, 200, GSL_INTEG_GAUSS41, w, &duhamel, &err);
        gsl_integration_workspace_free(w);
        EXPECT_NEAR(terzaghi_excess_pressure(r, z, t), duhamel, 1e-6 * 1250.0) << "t_r " << tr << " t " << t << " z " << z;
      }
  }
}

// Sheet-pile seepage (reference/analytical/sheet_pile_seepage): the GSL evaluation of the thin-pile
// closed forms against every row of the tables derived for issue 18 (reference/analytical/
// sheet_pile_seepage_analytical_*.csv, printed to 4-5 digits), and the finite-volume Laplace solver at
// zero thickness on a wide domain against the closed forms. The solver's error is first order near
// the pile's tip (the crack-tip singularity) and second order elsewhere: 1% of H at grid T/80.
namespace {
std::vector<std::vector<std::string>> csv_rows(const std::string& name) {
  return geosph::verify::read_csv_rows((geosph::verify::default_data_dir() / "reference" / "analytical" / name).string());
}
}  // namespace

TEST(SheetPileSeepage, ClosedFormsMatchTheTables) {
  using geosph::reference::ThinSheetPile;
  const auto depth = csv_rows("sheet_pile_seepage_analytical_finite_depth.csv");
  ASSERT_EQ(depth.size(), 11u);
  for (const auto& r : depth) {
    const double sT = std::stod(r[0]);
    if (sT == 0) continue;  // the infinite-depth limit
    const ThinSheetPile p{sT};
    EXPECT_NEAR(p.discharge_over_kH(), std::stod(r[1]), 6e-5) << "s/T " << sT;
    EXPECT_NEAR(p.exit_gradient_at_face_times_T_over_H() * sT, std::stod(r[2]), 6e-6) << "s/T " << sT;
  }
  int face = 0, exit = 0;
  for (const auto& r : csv_rows("sheet_pile_seepage_analytical_profiles.csv")) {
    if (r[0] != "0.5") continue;
    const ThinSheetPile p{0.5};
    const double c = std::stod(r[3]), v = std::stod(r[4]);
    if (r[1] == "h_over_H_downstream_face") {
      EXPECT_NEAR(p.downstream_face_head(c * 0.5), v, 6e-6) << "depth/s " << c;
      ++face;
    } else if (r[1] == "exit_gradient_times_s_over_H") {
      EXPECT_NEAR(p.exit_gradient_times_T_over_H(c * 0.5) * 0.5, v, 6e-6) << "x/s " << c;
      ++exit;
    }
  }
  EXPECT_EQ(face, 11);
  EXPECT_EQ(exit, 6);
  // T -> infinity: Khosla's exit gradient H / (pi s) (the first table row)
  EXPECT_NEAR(ThinSheetPile{1e-4}.exit_gradient_at_face_times_T_over_H() * 1e-4, 1.0 / M_PI, 1e-6);
}

TEST(SheetPileSeepage, LaplaceSolverReproducesTheThinPile) {
  using namespace geosph::reference;
  const double T = 1.0;
  for (double sT : {0.3, 0.5}) {
    const ThinSheetPile a{sT};
    const SheetPileLaplace fd({T, 4.0 * T, sT * T, 0.0, T / 80});
    EXPECT_NEAR(fd.discharge_over_kH(), a.discharge_over_kH(), 0.01 * a.discharge_over_kH()) << "s/T " << sT;
    EXPECT_NEAR(fd.head(0.0, -sT * T - T / 160), 0.5, 1e-9);  // antisymmetry, half a cell below the tip
    for (double d : {0.2, 0.5, 0.8})
      EXPECT_NEAR(fd.head(1e-6, -d * sT * T), a.downstream_face_head(d * sT), 0.01) << "s/T " << sT << " depth/s " << d;
    // head at one grid cell below the downstream surface: the exit gradient over that depth
    for (double x : {0.1, 0.5})
      EXPECT_NEAR(fd.head(x, -T / 160) / (T / 160), a.exit_gradient_times_T_over_H(x), 0.02) << "s/T " << sT << " x " << x;
  }
  // a thick pile lengthens the flow path: less discharge; the toe head stays H/2 by antisymmetry
  const SheetPileLaplace thin({T, 2.0, 0.5, 0.0, T / 40}), thick({T, 2.0, 0.5, 0.2, T / 40});
  EXPECT_LT(thick.discharge_over_kH(), thin.discharge_over_kH());
  EXPECT_NEAR(thick.head(0.0, -0.5 - T / 80), 0.5, 1e-9);
  EXPECT_THROW(SheetPileLaplace({T, 2.0, 0.5, 0.2, 0.03}), std::invalid_argument);
}
