// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file PointLocator.h
/// Uniform bucket grid over a point cloud for nearest-neighbour queries: the
/// search behind h_P (4.36) and the exact distance near the points (4.4.2).
/// Buckets are stored compressed (CSR): no per-bucket allocation.

#include "sltk/cloud/PointCloud.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace sltk
{

/// The locator's points per bucket unless a caller chooses (recon/CloudPreparation.h chooses 16).
constexpr double PointLocatorDefaultBucket = 2.0;

template <int D>
class PointLocator
{
public:
  /// Result of a nearest-point query.
  struct Hit
  {
    std::int64_t Index = -1; ///< -1 when the cloud has no other point
    double Distance = std::numeric_limits<double>::infinity();
  };

  /// Buckets the cloud (which must stay alive and unchanged) so that there
  /// are about `pointsPerBucket` points per non-empty bucket on a surface-like
  /// cloud. Its bucket table and point order are 32-bit (4 bytes a point and
  /// 4 a bucket less than 64-bit ones): a cloud of more than
  /// MaximumIndexedPoints (PointCloud.h), which the entry points refuse first,
  /// throws std::length_error (a caller that skipped the checks).
  explicit PointLocator(const PointCloud<D>& cloud, double pointsPerBucket = PointLocatorDefaultBucket);

  /// Nearest cloud point to x, skipping the point with index `exclude` (-1: none).
  Hit nearest(const std::array<double, D>& x, std::int64_t exclude = -1) const;

  /// nearest(x) when the nearest point lies within `radius` (inclusive), else
  /// no hit (Index -1, Distance +inf): the search stops at the radius, so a
  /// query far from the cloud is as cheap as a near one.
  Hit nearestWithin(const std::array<double, D>& x, double radius) const;

  /// The k nearest cloud points to x, nearest first (ties by index), skipping
  /// `exclude`; fewer when the cloud has fewer other points. `hits` is reused.
  void nearest(const std::array<double, D>& x, int k, std::int64_t exclude, std::vector<Hit>& hits) const;

  /// Every cloud point closer than `radius` to x, skipping `exclude`, in the buckets'
  /// order (the links of the cloud's components, recon/PointClusters.h). `found` is reused.
  void within(
    const std::array<double, D>& x, double radius, std::int64_t exclude, std::vector<std::int64_t>& found) const;

  /// nearest(x[i]).Distance for the `count` points x (close together: a
  /// tile's nodes), bit for bit. The nearest point to any of them lies within
  /// |the centre's nearest| + 2 spread of their centre (the triangle
  /// inequality; spread: the farthest of them from it), so one ring search at
  /// the centre and one ball of candidates serve them all, and sqrt is
  /// monotone and correctly rounded. A ball of more than `maxCandidates`
  /// points falls back to a query per point. `candidates` is reused.
  void nearestDistances(const std::array<double, D>* x, std::int64_t count, double* distances,
    std::vector<std::int64_t>& candidates, std::int64_t maxCandidates = 1024) const;

  double bucketSize() const { return this->Size; }
  const PointCloud<D>& cloud() const { return *this->Cloud; }

private:
  std::int64_t bucketOf(const std::array<std::int64_t, D>& b) const;

  /// Ring search around x: visit(q, d) for every point q != exclude in rings of
  /// buckets until reach() (the current search radius, +inf while unknown) is
  /// no farther than the next ring.
  template <class Visit, class Reach>
  void search(const std::array<double, D>& x, std::int64_t exclude, Visit&& visit, Reach&& reach) const;

  const PointCloud<D>* Cloud;
  Box<D> Bounds;
  double Size = 1.0;
  std::array<std::int64_t, D> Count{};
  std::vector<std::uint32_t> Start;  ///< CSR offsets, one per bucket + 1
  std::vector<std::uint32_t> Points; ///< point indices grouped by bucket
  /// Their coordinates in the same order: a bucket's candidates are read from
  /// consecutive memory, not gathered from the cloud by index.
  std::vector<std::array<double, D>> Coordinates;
};

extern template class PointLocator<2>;
extern template class PointLocator<3>;

} // namespace sltk
