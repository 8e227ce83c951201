// Shared helpers of the material-point model tests: parameter validation (soil::validate
// overloads) and a rotation about z.
#pragma once
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>

#include <stdexcept>
#include <string>

namespace geosph::test {

// validate(p) must throw std::invalid_argument whose message names `field` and says what it must be,
// and so must the model's constructor.
template <class Model, class Params>
void expect_rejects(const Params& p, const std::string& field) {
  try {
    validate(p);  // found by argument-dependent lookup (geosph::soil)
    ADD_FAILURE() << field << ": accepted";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(field), std::string::npos) << msg;
    EXPECT_NE(msg.find("must be"), std::string::npos) << msg;
  }
  EXPECT_THROW(Model{p}, std::invalid_argument);
}

// Rotation by theta about the z axis.
inline Eigen::Matrix3d rotation_z(double theta) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  R(0, 0) = R(1, 1) = std::cos(theta);
  R(1, 0) = std::sin(theta);
  R(0, 1) = -std::sin(theta);
  return R;
}

}  // namespace geosph::test
