// The Poiseuille start-up series (Morris et al. 1997, eq. 21): limits and symmetry.
#include <gtest/gtest.h>

#include <cmath>

#include "analytical/poiseuille.hpp"
#include "analytical/terzaghi_consolidation.hpp"

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
