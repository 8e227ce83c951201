// The Poiseuille start-up series (Morris et al. 1997, eq. 21): limits and symmetry.
#include <gtest/gtest.h>

#include "analytical/poiseuille.hpp"

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
