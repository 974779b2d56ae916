// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudNoise.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace sltk
{

namespace
{
/// The root mean square residual of the quadric (D = 3: 1, u, v, u^2, uv, v^2;
/// D = 2: 1, u, u^2) that fits the points' heights over their principal
/// tangent axes, over the residual's degrees of freedom.
template <int D>
double quadricResidual(
  const PointCloud<D>& cloud, std::int64_t centre, const std::vector<typename PointLocator<D>::Hit>& hits)
{
  constexpr int Terms = D == 3 ? 6 : 3;
  const int m = static_cast<int>(hits.size()) + 1;
  Eigen::Matrix<double, Eigen::Dynamic, D> q(m, D);
  for (int r = 0; r < m; ++r)
  {
    const auto& p = cloud.Points[static_cast<size_t>(r == 0 ? centre : hits[static_cast<size_t>(r - 1)].Index)];
    for (int a = 0; a < D; ++a)
    {
      q(r, a) = p[a];
    }
  }
  q.rowwise() -= q.colwise().mean();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> axes(q.transpose() * q);
  const Eigen::Matrix<double, Eigen::Dynamic, D> local = q * axes.eigenvectors(); // column 0: the normal
  Eigen::MatrixXd terms(m, Terms);
  for (int r = 0; r < m; ++r)
  {
    const double u = local(r, 1), v = D == 3 ? local(r, D - 1) : 0.0;
    terms(r, 0) = 1.0;
    terms(r, 1) = u;
    if (D == 3)
    {
      terms(r, 2) = v;
      terms(r, 3) = u * u;
      terms(r, 4) = u * v;
      terms(r, 5) = v * v;
    }
    else
    {
      terms(r, 2) = u * u;
    }
  }
  const Eigen::VectorXd height = local.col(0);
  const Eigen::VectorXd fit = terms.colPivHouseholderQr().solve(height);
  return std::sqrt((height - terms * fit).squaredNorm() / static_cast<double>(m - Terms));
}
} // namespace

template <int D>
Status cloudNoise(const PointLocator<D>& locator, double cloudSpacing, const Context& ctx, double& noise)
{
  const PointCloud<D>& cloud = locator.cloud();
  const Index n = static_cast<Index>(cloud.size());
  if (n < NoiseNeighbours + 1 || !(cloudSpacing > 0.0))
  {
    return Status::invalidArgument("the cloud's noise needs at least " + std::to_string(NoiseNeighbours + 1) +
      " points and a positive h_P (" + std::to_string(n) + " points)");
  }
  const Index stride = (n + NoiseSamples - 1) / NoiseSamples;
  const Index samples = (n + stride - 1) / stride;
  std::vector<double> residuals(static_cast<size_t>(samples));
  ctx.parallelFor(0, samples,
    [&](Index b, Index e)
    {
      std::vector<typename PointLocator<D>::Hit> hits;
      for (Index s = b; s < e; ++s)
      {
        const std::int64_t centre = s * stride;
        locator.nearest(cloud.Points[static_cast<size_t>(centre)], NoiseNeighbours - 1, centre, hits);
        residuals[static_cast<size_t>(s)] = quadricResidual<D>(cloud, centre, hits);
      }
    });
  const auto middle = residuals.begin() + (samples - 1) / 2;
  std::nth_element(residuals.begin(), middle, residuals.end());
  noise = *middle / cloudSpacing;
  return Status::ok();
}

template Status cloudNoise(const PointLocator<2>&, double, const Context&, double&);
template Status cloudNoise(const PointLocator<3>&, double, const Context&, double&);

} // namespace sltk
