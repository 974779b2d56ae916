// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudNoise.h"

#include "SampleOnOwners.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
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
/// The checks of the noise's inputs for a cloud of n points.
Status checkNoiseInputs(std::int64_t n, double cloudSpacing)
{
  if (n < NoiseNeighbours + 1 || !(cloudSpacing > 0.0))
  {
    return Status::invalidArgument("the cloud's noise needs at least " + std::to_string(NoiseNeighbours + 1) +
      " points and a positive h_P (" + std::to_string(n) + " points)");
  }
  return Status::ok();
}

/// The sampled points of a cloud of n points: every stride-th, at most NoiseSamples.
std::vector<std::int64_t> noiseSample(std::int64_t n)
{
  const std::int64_t stride = (n + NoiseSamples - 1) / NoiseSamples;
  std::vector<std::int64_t> sample(static_cast<size_t>((n + stride - 1) / stride));
  for (size_t s = 0; s < sample.size(); ++s)
  {
    sample[s] = static_cast<std::int64_t>(s) * stride;
  }
  return sample;
}

/// The fit's residual about point `centre` of the locator's cloud, and the farthest neighbour it used.
template <int D>
OwnedAnswer residualAbout(
  const PointLocator<D>& locator, std::int64_t centre, std::vector<typename PointLocator<D>::Hit>& hits)
{
  locator.nearest(locator.cloud().Points[static_cast<size_t>(centre)], NoiseNeighbours - 1, centre, hits);
  if (static_cast<int>(hits.size()) < NoiseNeighbours - 1)
  {
    return { 0.0, std::numeric_limits<double>::infinity() };
  }
  return { quadricResidual<D>(locator.cloud(), centre, hits), hits.back().Distance };
}

/// The median residual in units of h_P.
double medianNoise(std::vector<double>& residuals, double cloudSpacing)
{
  const auto middle = residuals.begin() + static_cast<std::ptrdiff_t>(residuals.size() - 1) / 2;
  std::nth_element(residuals.begin(), middle, residuals.end());
  return *middle / cloudSpacing;
}
} // namespace

template <int D>
Status cloudNoise(const PointLocator<D>& locator, double cloudSpacing, const Context& ctx, double& noise)
{
  SLTK_RETURN_IF_ERROR(checkNoiseInputs(locator.cloud().size(), cloudSpacing));
  const std::vector<std::int64_t> sample = noiseSample(locator.cloud().size());
  std::vector<double> residuals(sample.size());
  ctx.parallelFor(0, static_cast<Index>(sample.size()),
    [&](Index b, Index e)
    {
      std::vector<typename PointLocator<D>::Hit> hits;
      for (Index s = b; s < e; ++s)
      {
        residuals[static_cast<size_t>(s)] = residualAbout(locator, sample[static_cast<size_t>(s)], hits).Value;
      }
    });
  noise = medianNoise(residuals, cloudSpacing);
  return Status::ok();
}

template <int D>
Status cloudNoiseOnRanks(const OwnedPoints<D>& points, std::int64_t total, double cloudSpacing,
  const Communicator& comm, const Context& ctx, double& noise)
{
  SLTK_RETURN_IF_ERROR(checkNoiseInputs(total, cloudSpacing));
  SLTK_RETURN_IF_ERROR(checkTotal(points, total, comm));
  std::vector<double> residuals;
  std::int64_t remote = 0;
  SLTK_RETURN_IF_ERROR(
    sampleOnOwners(points, noiseSample(total), NoiseNeighbours - 1, comm, ctx, residualAbout<D>, residuals, remote));
  noise = medianNoise(residuals, cloudSpacing);
  return Status::ok();
}

template Status cloudNoise(const PointLocator<2>&, double, const Context&, double&);
template Status cloudNoise(const PointLocator<3>&, double, const Context&, double&);
template Status cloudNoiseOnRanks(
  const OwnedPoints<2>&, std::int64_t, double, const Communicator&, const Context&, double&);
template Status cloudNoiseOnRanks(
  const OwnedPoints<3>&, std::int64_t, double, const Communicator&, const Context&, double&);

} // namespace sltk
