// Tait equation of state: inverse consistency and the closed-form hydrostatic column against the
// independent GSL integration in reference/analytical/hydrostatic_tait.
#include <gtest/gtest.h>

#include <cmath>

#include "analytical/hydrostatic_tait.hpp"
#include "fluid/equation_of_state.hpp"

using namespace geosph;

namespace {
FluidMaterial water(double c0) {
  FluidMaterial m;
  m.name = "water"; m.density = 1000; m.sound_speed = c0; m.gamma = 7;
  return m;
}
}  // namespace

TEST(TaitEos, PressureAndDensityAreInverse) {
  const TaitEos eos(water(20));
  EXPECT_DOUBLE_EQ(eos.pressure(1000), 0.0);
  for (double rho : {980.0, 1000.0, 1003.0, 1050.0}) EXPECT_NEAR(eos.density(eos.pressure(rho)), rho, 1e-9);
  // linearised: dp/drho = c0^2 at rho0
  EXPECT_NEAR((eos.pressure(1000.001) - eos.pressure(999.999)) / 0.002, 400.0, 1e-3);
}

TEST(TaitEos, HydrostaticClosedFormMatchesOdeIntegration) {
  const double g = 9.81, H0 = 0.4;
  const TaitEos eos(water(20));
  const reference::HydrostaticTait ref(1000, 20, 7, g, H0);
  for (double depth : {0.0, 0.05, 0.2, 0.39})
    EXPECT_NEAR(eos.hydrostatic_pressure(g, depth), ref.pressure_at_depth(depth), 1e-7 * 1000 * g * H0);
}

// pressure_head inverts hydrostatic_pressure: the depth at which resting Tait water has pressure p
TEST(TaitEos, PressureHeadInvertsTheHydrostaticPressure) {
  const TaitEos eos(water(20));
  for (double depth : {0.0, 0.05, 0.2, 1.3})
    EXPECT_NEAR(eos.pressure_head(9.81, eos.hydrostatic_pressure(9.81, depth)), depth, 1e-12);
  // water is denser under pressure, so rho0 g d is reached above the depth d
  EXPECT_LT(eos.pressure_head(9.81, 1000 * 9.81 * 0.2), 0.2);
}

TEST(TaitEos, IncompressibleLimitIsRhoGH) {
  const TaitEos eos(water(1e5));
  EXPECT_NEAR(eos.hydrostatic_pressure(9.81, 0.5), 1000 * 9.81 * 0.5, 1e-6 * 4905);
  const reference::HydrostaticTait ref(1000, 1e5, 7, 9.81, 0.5);
  EXPECT_NEAR(ref.surface_height(), 0.5, 1e-9);
}

TEST(HydrostaticTait, CompressedColumnConservesMass) {
  // a compressible column settles below its uniform-density height H0
  const reference::HydrostaticTait ref(1000, 10, 7, 9.81, 0.4);
  EXPECT_LT(ref.surface_height(), 0.4);
  EXPECT_GT(ref.surface_height(), 0.4 * (1 - 0.05));
  EXPECT_NEAR(ref.pressure(ref.surface_height()), 0.0, 1e-9);
}

// A whole-number gamma is raised by squaring: the same pressure as std::pow to rounding.
TEST(TaitEos, WholeNumberGammaMatchesPow) {
  for (double gamma : {1.0, 2.0, 7.0, 16.0}) {
    FluidMaterial m = water(30);
    m.gamma = gamma;
    const TaitEos eos(m);
    EXPECT_EQ(eos.integer_gamma, static_cast<int>(gamma));
    for (double rho : {950.0, 999.0, 1000.0, 1001.5, 1080.0}) {
      const double exact = eos.B * (std::pow(rho / 1000.0, gamma) - 1.0);
      EXPECT_NEAR(eos.pressure(rho), exact, 1e-12 * eos.B) << "gamma " << gamma << ", rho " << rho;
    }
  }
  FluidMaterial m = water(30);
  m.gamma = 7.5;
  EXPECT_EQ(TaitEos(m).integer_gamma, 0);
}
