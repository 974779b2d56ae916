// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudPoints.h
/// The cloud the steps before the first grid read: the validation, the
/// cleaning (CloudCleaning.h), the unit box (4.5), h_P (4.36), the noise, the
/// density spacing, the thinning and the local offset's rho (recon/ReconstructionPlan.h). Held whole on
/// one rank (WholeCloud) or spread over the ranks by owners (OwnedCloud,
/// PointOwners.h), each step gives the same value on both, bit for bit, so one
/// implementation of the steps serves both (Documentation/Distributed.md,
/// "Points to their owners"). The steps are called a few times a plan, never
/// in a loop over points.

#include "sltk/cloud/CloudNoise.h"
#include "sltk/cloud/CloudOutliers.h"
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/cloud/CloudThinning.h"
#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace sltk
{

/// A change of units applied to every point (the unit box's, UnitBox.h).
template <int D>
using PointMap = std::function<std::array<double, D>(const std::array<double, D>&)>;

template <int D>
class CloudPoints
{
public:
  virtual ~CloudPoints() = default;
  /// The cloud's points (over every rank).
  virtual std::int64_t size() const = 0;
  /// validateCloud() of the cloud (PointCloud.h).
  virtual Status validate() const = 0;
  /// boundingBox() of the cloud.
  virtual Box<D> box() const = 0;
  /// Every point p replaced by map(p), the order kept.
  virtual Status transform(const PointMap<D>& map) = 0;
  /// removeOutliers() (CloudOutliers.h): the cloud becomes the kept points, in their order.
  virtual Status removeOutliers(const OutlierOptions& options, const Context& ctx, OutlierReport& report) = 0;
  /// cloudSpacing() (CloudSpacing.h): h_P (4.36), or the density spacing with options.DensityNeighbours.
  virtual Status spacing(const Context& ctx, const CloudSpacingOptions& options, double& spacing) const = 0;
  /// cloudNoise() (CloudNoise.h) in units of `cloudSpacing`.
  virtual Status noise(double cloudSpacing, const Context& ctx, double& noise) const = 0;
  /// thinCloud() (CloudThinning.h): the cloud becomes the cell means, in cell order.
  virtual Status thin(double cell) = 0;
  /// sparsityFactors() (LocalSpacing.h: rho of the local offset, LocalOffset.h)
  /// of every point with k neighbours, in the cloud's order, on every rank. Collective.
  virtual Status sparsity(int k, const Context& ctx, std::vector<double>& factors) const = 0;
  /// The whole cloud, in its order, in `cloud` on every rank, and a locator on
  /// it with `pointsPerBucket` (the cloud must then stay where it is). Collective.
  virtual Status release(
    PointCloud<D>& cloud, double pointsPerBucket, std::unique_ptr<const PointLocator<D>>& locator) = 0;
  /// The most points any rank holds (its own and its halo), over every rank. Collective.
  virtual std::int64_t heldMax() const = 0;
};

/// The cloud held whole on one rank: the steps are the one-rank functions,
/// on one locator built when a step first needs it.
template <int D>
class WholeCloud final : public CloudPoints<D>
{
public:
  /// Works in place on `cloud`, which must outlive this view.
  WholeCloud(PointCloud<D>& cloud, double pointsPerBucket);

  std::int64_t size() const override { return this->Cloud.size(); }
  Status validate() const override;
  Box<D> box() const override;
  Status transform(const PointMap<D>& map) override;
  Status removeOutliers(const OutlierOptions& options, const Context& ctx, OutlierReport& report) override;
  Status spacing(const Context& ctx, const CloudSpacingOptions& options, double& spacing) const override;
  Status noise(double cloudSpacing, const Context& ctx, double& noise) const override;
  Status thin(double cell) override;
  Status sparsity(int k, const Context& ctx, std::vector<double>& factors) const override;
  Status release(
    PointCloud<D>& cloud, double pointsPerBucket, std::unique_ptr<const PointLocator<D>>& locator) override;
  std::int64_t heldMax() const override { return this->Cloud.size(); }

private:
  const PointLocator<D>& locator() const;

  PointCloud<D>& Cloud;
  double PointsPerBucket;
  mutable std::unique_ptr<const PointLocator<D>> Locator;
};

/// The cloud spread over the ranks by slabs of about equal numbers of points
/// (balancedCuts, sendToOwners): the steps are the *OnRanks functions, each
/// the one-rank value bit for bit. A change of units moves the points to the
/// owners of their new places (new cuts: a cut moved with the points could
/// round onto a point and change its owner).
template <int D>
class OwnedCloud final : public CloudPoints<D>
{
public:
  explicit OwnedCloud(const Communicator& comm);

  /// The ranks' shares of the cloud (this rank's: `share`, global indices
  /// firstId, firstId + 1, ...) sent to their owners. Collective.
  Status own(const PointCloud<D>& share, std::int64_t firstId);

  std::int64_t size() const override { return this->Total; }
  Status validate() const override;
  Box<D> box() const override;
  Status transform(const PointMap<D>& map) override;
  Status removeOutliers(const OutlierOptions& options, const Context& ctx, OutlierReport& report) override;
  Status spacing(const Context& ctx, const CloudSpacingOptions& options, double& spacing) const override;
  Status noise(double cloudSpacing, const Context& ctx, double& noise) const override;
  Status thin(double cell) override;
  Status sparsity(int k, const Context& ctx, std::vector<double>& factors) const override;
  Status release(
    PointCloud<D>& cloud, double pointsPerBucket, std::unique_ptr<const PointLocator<D>>& locator) override;
  std::int64_t heldMax() const override;

private:
  /// This rank's own points sent again to their owners under new balanced cuts.
  Status reown();
  /// Refuses a cloud of more than MaximumIndexedPoints, before it is gathered.
  Status indexable() const;

  const Communicator& Comm;
  OwnedPoints<D> Owned;
  std::int64_t Total = 0;
  std::int64_t HeldMax = 0; ///< the most points held by a rank so far
};

extern template class WholeCloud<2>;
extern template class WholeCloud<3>;
extern template class OwnedCloud<2>;
extern template class OwnedCloud<3>;

} // namespace sltk
