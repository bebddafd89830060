// The quadratic error function of Dual Contouring and its truncated-SVD minimiser (Ju, Losasso,
// Schaefer & Warren, "Dual contouring of Hermite data", SIGGRAPH 2002, section 2.3). See qef.hpp.
#include "qef.hpp"

#include <Eigen/SVD>

namespace isopatch::bench {

void Qef::add(const Vec3& point, const Vec3& normal) {
  ata_ += normal * normal.transpose();
  atb_ += normal * normal.dot(point);
  point_sum_ += point;
  ++count_;
}

Vec3 Qef::mass_point() const {
  return count_ == 0 ? Vec3::Zero() : Vec3(point_sum_ / static_cast<double>(count_));
}

Vec3 Qef::minimiser(double truncation) const {
  // With x = c + y (c the mass point), E is minimal where A^T A y = A^T b - A^T A c; of the solutions
  // of the truncated system, the pseudo-inverse gives the one with the smallest |y|.
  const Vec3 c = mass_point();
  const Vec3 rhs = atb_ - ata_ * c;
  const Eigen::JacobiSVD<Mat3> svd(ata_, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Vec3& sigma = svd.singularValues();  // descending
  if (!(sigma[0] > 0.0)) return c;
  Vec3 y = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    if (sigma[i] < truncation * sigma[0]) break;
    y += svd.matrixV().col(i) * (svd.matrixU().col(i).dot(rhs) / sigma[i]);
  }
  return c + y;
}

}  // namespace isopatch::bench
