// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file RunPoints.h
/// The points a rank's run reads on slabs (Documentation/Distributed.md, "The
/// runs on the ranks' own points"): those of the plan's cloud within `Reach` of
/// the rank's window along the last axis, in the cloud's order, with their own
/// locator. Every point nearer than Reach to a node of the window is held, so a
/// nearest distance found among them that is at most Reach is the whole cloud's,
/// bit for bit (the same point, the same arithmetic; ties go to the lower index
/// in both, the order being kept). A farther one is settled over the ranks
/// (ExactDistanceCache.h). On one rank, or when a rank's window would hold no
/// point, every rank reads the plan's cloud and locator as before. The runs'
/// grids are not periodic (RunSlab::plan), so the distance along the last axis
/// bounds the distance to a point; every point lies in some rank's selection,
/// which the settling over the ranks needs.
///
/// Today the plan still gathers the whole cloud on every rank (its statistics);
/// these points are selected from it, so a rank's runs query and scan only
/// its share while the plan's cloud stays for the statistics and the summary.

#include "sltk/cloud/PointLocator.h"
#include "sltk/exec/Communicator.h"
#include "sltk/recon/CloudPreparation.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace sltk
{

template <int D>
class RunPoints
{
public:
  /// How far run `run`'s points reach beyond its window on `grid`: gamma and
  /// two cell diagonals (the band's stencils, the exact boxes of 4.4.2) beyond
  /// where its band lies. Run 1's surface lies up to K_P h_P max(rho) from the
  /// cloud (4.4.4, LocalOffset.h; K_P = `outsideFactor`); an ellipsoid's may lie
  /// anywhere, so that run holds every point. A later run's surface lies near
  /// the cloud (Err_P is a fraction of a cell), so 4 h_P more covers it but where
  /// it bridges a hole wider than that: the few band nodes there are settled
  /// over the ranks (ExactDistanceCache.h).
  static double reachFor(const ReconstructionPlan<D>& plan, const GridSpec<D>& grid, int run, double outsideFactor)
  {
    if (run == 1 && plan.InitialEllipsoid)
    {
      return std::numeric_limits<double>::infinity();
    }
    double diagonal = 0.0;
    for (int a = 0; a < D; ++a)
    {
      diagonal += grid.Spacing[a] * grid.Spacing[a];
    }
    const double beyond = plan.Options.GammaFactor * grid.Spacing[0] + 2.0 * std::sqrt(diagonal);
    const double sparsest = plan.Sparsity.empty() ? 1.0 : *std::max_element(plan.Sparsity.begin(), plan.Sparsity.end());
    return beyond + (run == 1 ? outsideFactor * sparsest : 4.0) * plan.CloudSpacing;
  }

  /// The interval along the last axis whose points a rank's run reads: `window`'s
  /// rows, `ghost` layers and a row more beyond them, and `reach` (pointsInIntervals,
  /// PointOwners.h, sends the owners' points in it).
  static std::array<double, 2> rowsReached(const GridSpec<D>& window, int ghost, double reach)
  {
    const double dz = window.Spacing[D - 1];
    return { window.coordinate(D - 1, 0) - (ghost + 1) * dz - reach,
      window.coordinate(D - 1, window.Dims[D - 1] - 1) + (ghost + 1) * dz + reach };
  }

  /// The points of `plan`'s cloud within `reach` of `window`'s rows along the
  /// last axis (`ghost` layers of its fields beyond them and a row more
  /// included). Collective: when any rank's share is empty, or on one rank,
  /// every rank takes the whole cloud.
  void select(
    const ReconstructionPlan<D>& plan, const GridSpec<D>& window, int ghost, double reach, const Communicator& comm)
  {
    this->Plan = &plan;
    this->Reach = reach;
    this->Own.reset();
    this->Original.clear();
    this->Sparsity.clear();
    this->Points.Points.clear();
    if (comm.size() == 1 || !std::isfinite(reach))
    {
      this->Reach = std::numeric_limits<double>::infinity();
      return;
    }
    const auto [low, high] = rowsReached(window, ghost, reach);
    const std::vector<std::array<double, D>>& all = plan.Cloud.Points;
    for (size_t k = 0; k < all.size(); ++k)
    {
      if (all[k][D - 1] >= low && all[k][D - 1] <= high)
      {
        this->Original.push_back(static_cast<Index>(k));
      }
    }
    if (comm.anyRank(this->Original.empty()))
    {
      this->Original.clear();
      this->Reach = std::numeric_limits<double>::infinity();
      return;
    }
    this->Points.Points.reserve(this->Original.size());
    for (const Index k : this->Original)
    {
      this->Points.Points.push_back(all[static_cast<size_t>(k)]);
      if (!plan.Sparsity.empty())
      {
        this->Sparsity.push_back(plan.Sparsity[static_cast<size_t>(k)]);
      }
    }
    this->Own = std::make_unique<const PointLocator<D>>(this->Points, ReconstructionPointsPerBucket);
  }

  /// The points this rank reads (the plan's cloud when not selected).
  const PointCloud<D>& cloud() const { return this->Own ? this->Points : this->Plan->Cloud; }
  const PointLocator<D>& locator() const { return this->Own ? *this->Own : *this->Plan->Locator; }
  /// rho of each of cloud()'s points (LocalOffset.h), empty when the plan has none.
  const std::vector<double>& sparsity() const { return this->Own ? this->Sparsity : this->Plan->Sparsity; }
  /// The index in the plan's cloud of cloud()'s point k.
  Index original(Index k) const { return this->Own ? this->Original[static_cast<size_t>(k)] : k; }
  /// Every point nearer than this to a node of the window is held (infinite: all are).
  double reach() const { return this->Reach; }
  /// The points of the whole cloud (the denominators of Err_P and the far fraction).
  Index total() const { return this->Plan->Cloud.size(); }
  Index held() const { return this->cloud().size(); }

private:
  const ReconstructionPlan<D>* Plan = nullptr;
  double Reach = std::numeric_limits<double>::infinity();
  PointCloud<D> Points;
  std::vector<Index> Original;
  std::vector<double> Sparsity;
  std::unique_ptr<const PointLocator<D>> Own;
};

} // namespace sltk
