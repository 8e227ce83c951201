// The slip-line reader of the retaining-wall case (harness/slip_line.hpp) on synthetic displacement
// fields: a rigid wedge above a plane through the wall's foot at a known angle moves with the wall and
// the ground below stays, so the slip points lie on that plane and the fitted angle is the plane's to
// within the bin width over the fitted height.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "harness/slip_line.hpp"

using namespace geosph::verify;

namespace {

// a lattice of spacing dx over [0, Lb] x [0, H]; inside the wedge (y > x tan(angle)) ux = travel
SlipLine wedge(double angle_deg, double travel, double dx, double Lb = 0.3, double H = 0.1) {
  const double t = std::tan(angle_deg * std::numbers::pi / 180.0);
  std::vector<double> x0, y0, ux;
  for (double x = 0.5 * dx; x < Lb; x += dx)
    for (double y = 0.5 * dx; y < H; y += dx) {
      x0.push_back(x);
      y0.push_back(y);
      ux.push_back(y > x * t ? travel : 0.0);
    }
  return slip_line(x0, y0, ux, H, Lb, dx, travel);
}

}  // namespace

TEST(SlipLine, FindsTheActivePlaneOfARigidWedge) {
  for (double angle : {50.0, 55.0, 60.0}) {
    const SlipLine s = wedge(angle, -0.01, 0.0025);
    EXPECT_NEAR(s.angle_deg, angle, 1.0) << angle;
    EXPECT_GE(s.x.size(), 8u);
  }
}

TEST(SlipLine, FindsThePassivePlaneOfARigidWedge) {
  for (double angle : {30.0, 35.0, 40.0}) {
    const SlipLine s = wedge(angle, 0.03, 0.0025);
    EXPECT_NEAR(s.angle_deg, angle, 1.0) << angle;
  }
}

TEST(SlipLine, UniformStrainHasNoWedge) {
  // the whole backfill stretching uniformly (a smooth floor): ux falls linearly from the wall's travel
  // at x = 0 to zero at Lb, so the half-travel point is Lb / 2 at every height: a vertical line
  const double Lb = 0.3, H = 0.1, dx = 0.005, travel = -0.01;
  std::vector<double> x0, y0, ux;
  for (double x = 0.5 * dx; x < Lb; x += dx)
    for (double y = 0.5 * dx; y < H; y += dx) {
      x0.push_back(x);
      y0.push_back(y);
      ux.push_back(travel * (1 - x / Lb));
    }
  const SlipLine s = slip_line(x0, y0, ux, H, Lb, dx, travel);
  ASSERT_GE(s.x.size(), 8u);
  for (double xs : s.x) EXPECT_NEAR(xs, 0.5 * Lb / H, dx / H);
  // height regressed on x: a vertical line has no finite slope (NaN, which fails a scored angle), a
  // nearly vertical one a steep angle; neither reads as a wedge
  EXPECT_TRUE(std::isnan(s.angle_deg) || s.angle_deg > 80.0) << s.angle_deg;
}

TEST(SlipLine, WedgeAngleNeedsThreePointsInTheFittedHeight) {
  EXPECT_TRUE(std::isnan(wedge_angle_deg({0.1, 0.2}, {0.3, 0.5})));
  EXPECT_NEAR(wedge_angle_deg({0.1, 0.2, 0.3, 0.9}, {0.2, 0.4, 0.6, 0.95}), std::atan(2.0) * 180 / std::numbers::pi,
              1e-9);
}

TEST(SlipLine, WedgeAngleFitsTheEightInteriorStrips) {
  // slip points at the ten strip centres: the eight interior ones on a 45 deg line, the bottom and top
  // strips far off it; the fit must take all eight (centres 0.15 and 0.85 included) and neither end
  std::vector<double> x, y;
  for (int k = 0; k < 10; ++k) {
    const double yc = 0.05 + 0.1 * k;
    y.push_back(yc);
    x.push_back(k == 0 || k == 9 ? 5.0 : yc);
  }
  EXPECT_NEAR(wedge_angle_deg(x, y), 45.0, 1e-9);
  // the points at 0.15 and 0.85 lie off the line: leaving either out would not give this angle
  x[1] = 0.25;
  x[8] = 0.95;
  const double with_ends = wedge_angle_deg(x, y);
  x.erase(x.begin() + 8), y.erase(y.begin() + 8), x.erase(x.begin() + 1), y.erase(y.begin() + 1);
  EXPECT_NEAR(wedge_angle_deg(x, y), 45.0, 1e-9);
  EXPECT_GT(std::abs(with_ends - 45.0), 1.0);
}
