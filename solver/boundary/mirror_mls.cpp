#include "boundary/mirror_mls.hpp"

#include <Eigen/Dense>

namespace geosph {

bool mls_coefficients(const std::vector<MirrorNeighbour>& nb, int dim, double c[4]) {
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  for (const auto& q : nb) {
    const double b[4] = {1.0, q.b[0], q.b[1], q.b[2]};
    for (int r = 0; r <= dim; ++r)
      for (int s = 0; s <= dim; ++s) A(r, s) += b[r] * b[s] * q.wv;
  }
  for (int r = dim + 1; r < 4; ++r) A(r, r) = 1.0;  // 2D: the z row is not part of the fit
  const Eigen::LDLT<Eigen::Matrix4d> ldlt(A);
  // rcond of a full support with unit Shepard sum is of order 0.1 (the second moments of the kernel
  // in units of h^2); 1e-3 of that marks a support that does not span the dimension
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-4)) return false;
  const Eigen::Vector4d x = ldlt.solve(Eigen::Vector4d::UnitX());
  for (int r = 0; r < 4; ++r) c[r] = r <= dim ? x[r] : 0.0;
  return true;
}

Eigen::Matrix3d mirror_reflection(const double n[3], bool corner) {
  if (corner) {
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    for (int a = 0; a < 3; ++a)
      if (n[a] != 0) R(a, a) = -1.0;
    return R;
  }
  const Eigen::Vector3d v(n[0], n[1], n[2]);
  return Eigen::Matrix3d::Identity() - 2.0 * v * v.transpose();
}

}  // namespace geosph
