// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudThickness.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace sltk
{

template <int D>
FlatFit<D> fitFlat(const PointCloud<D>& cloud)
{
  using Vector = Eigen::Matrix<double, D, 1>;
  using Matrix = Eigen::Matrix<double, D, D>;
  FlatFit<D> fit;
  const double n = static_cast<double>(cloud.Points.size());
  Vector centre = Vector::Zero();
  for (const auto& p : cloud.Points)
  {
    centre += Eigen::Map<const Vector>(p.data()) / n;
  }
  Matrix covariance = Matrix::Zero();
  for (const auto& p : cloud.Points)
  {
    const Vector v = Eigen::Map<const Vector>(p.data()) - centre;
    covariance += v * v.transpose() / n;
  }
  const Eigen::SelfAdjointEigenSolver<Matrix> axes(covariance);
  const Vector normal = axes.eigenvectors().col(0); // eigenvalues in increasing order
  for (const auto& p : cloud.Points)
  {
    const Vector v = Eigen::Map<const Vector>(p.data()) - centre;
    fit.Thickness = std::max(fit.Thickness, std::fabs(v.dot(normal)));
  }
  for (int a = 0; a < D; ++a)
  {
    fit.Centre[a] = centre[a];
    fit.Normal[a] = normal[a];
  }
  return fit;
}

template FlatFit<2> fitFlat(const PointCloud<2>&);
template FlatFit<3> fitFlat(const PointCloud<3>&);

} // namespace sltk
