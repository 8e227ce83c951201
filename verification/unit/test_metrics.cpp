// Error measures of the verification harness.
#include <gtest/gtest.h>

#include <cmath>

#include "harness/metrics.hpp"

using namespace geosph::verify;

TEST(Metrics, RelativeL2AndObservedOrder) {
  EXPECT_NEAR(relative_l2({1.1, 2.0}, {1.0, 2.0}), 0.1 / std::sqrt(5.0), 1e-15);
  EXPECT_NEAR(observed_order(0.1, 0.04, 0.05, 0.01), 2.0, 1e-12);
  EXPECT_NEAR(interpolate({0, 1, 2}, {0, 10, 40}, 1.5), 25.0, 1e-12);
  EXPECT_NEAR(interpolate({0, 1, 2}, {0, 10, 40}, 5.0), 40.0, 1e-12);
}
