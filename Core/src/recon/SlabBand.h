// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SlabBand.h
/// The band storage of a run on its uniform grid (RunIterations.h): phi and d
/// on this rank's window of the grid (RunSlab.h; the whole grid on one rank),
/// the band B^n as a node list of the owned rows, ghost rows exchanged after
/// every update and the feet beyond the window answered by their owners
/// (FarFeetExchange.h).

#include "sltk/levelset/IsolatedNodes.h"
#include "sltk/levelset/NarrowBand.h"
#include "sltk/levelset/Reinitialise.h"
#include "sltk/levelset/ReinitialiseSlabs.h"
#include "sltk/recon/CloudError.h"
#include "sltk/recon/EnergyFunctional.h"
#include "sltk/recon/ExactDistanceCache.h"
#include "sltk/recon/FarFeetExchange.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/recon/Reconstruction.h"

#include "RunPoints.h"
#include "RunSlab.h"

#include <cmath>
#include <string>
#include <vector>

namespace sltk
{

/// The reinitialisation (1.38)-(1.45) of the owned nodes `nodes` on this rank's slab.
template <int D>
Status reinitialiseOn(GridField<D>& phi, const NodeList& nodes, const RunSlab<D>& slab, const ReinitOptions& options,
  const Context& ctx, ReinitWorkspace* workspace = nullptr)
{
  return reinitialiseSlabs<D>(phi, nodes, slab.slab(), slab.comm(), options, ctx, nullptr, workspace);
}

template <int D, class Interp>
class SlabBand
{
public:
  /// The band of phi (|phi| < gamma, (1.48)) on the owned rows; d made exact on it by prepare().
  SlabBand(const RunPoints<D>& points, const ReconstructionOptions& options, const Context& ctx,
    ExactDistanceCache<D>& exact, const RunSlab<D>& slab, GridField<D>& phi, GridField<D>& dist)
    : Points(points)
    , Options(options)
    , Ctx(ctx)
    , Exact(exact)
    , Slab(slab)
    , Phi(phi)
    , Dist(dist)
    , Gamma(BandWidths::forSpacing(phi.spec().Spacing[0], options.BetaFactor, options.GammaFactor).Gamma)
  {
    collectBand(phi, this->Gamma, ctx, this->Band); // (1.48)
    slab.keepOwned(this->Band);
    exact.reset(dist);
    slab.frameFarFeet(this->Far);
  }

  const GridSpec<D>& grid() const { return this->Slab.whole(); }

  Status prepare()
  {
    this->Exact.ensure(this->Band, this->Ctx, this->Dist);
    // On slabs d is made exact on the stencils of the ghost rows' band nodes
    // too: their stencils (one row) and dilation (1.53) reach the owned rows,
    // as the one-rank band does.
    this->Slab.ghostBand(this->Phi, this->Gamma, std::max<Index>(1, this->Options.ReinitDilation), this->GhostBand);
    this->Exact.ensure(this->GhostBand, this->Ctx, this->Dist);
    return Status::ok();
  }

  Status energy(const EnergyOptions& options, EnergyResult& ep)
  {
    SLTK_RETURN_IF_ERROR(this->Slab.agree(energyFunctional(this->Phi, this->Dist, this->Band, this->Ctx, ep, options)));
    reduceEnergy(ep, options, this->Slab.comm());
    return Status::ok();
  }

  /// The fraction of the cloud's points farther than `far` from the zero
  /// level set, |I[phi](Q)| > far, each rank counting the points of its owned cells.
  double farFraction(double far) const
  {
    const SlabPlan& s = this->Slab.slab();
    const double count = sumOverPoints<D, Interp>(this->Phi, this->Points.cloud(), this->Ctx, s.Begin, s.End,
      this->Slab.rows(), [far](double v) { return std::fabs(v) > far ? 1.0 : 0.0; });
    return this->Slab.sum(count) / static_cast<double>(this->Points.total());
  }

  /// This rank's points (those of its owned cells) with I[phi](Q) > threshold,
  /// ascending, numbered in the plan's cloud.
  std::vector<PlacedPoint<D>> outsidePoints(double threshold) const
  {
    const SlabPlan& s = this->Slab.slab();
    const std::vector<OutsidePoint> outside =
      pointsOutside<D, Interp>(this->Phi, this->Points.cloud(), threshold, s.Begin, s.End, this->Slab.rows());
    // The whole cloud's indices: the order is kept, still ascending.
    return placedPoints(outside, this->Points.cloud(), [this](Index k) { return this->Points.original(k); });
  }

  Status step(const LevelSetStepParameters& step)
  {
    // The step writes the band, the reinitialisation its dilation (1.53): phi^n there for eps_1 (4.34).
    // On slabs the ghost rows' band nodes dilate into the owned rows too.
    dilateBand(
      this->Phi.spec(), this->Band, this->Options.ReinitDilation, this->Ctx, this->ReinitBand, &this->GhostBand);
    this->Slab.keepOwned(this->ReinitBand);
    this->Previous.resize(this->ReinitBand.size());
    this->Ctx.parallelFor(0, static_cast<Index>(this->ReinitBand.size()),
      [&](Index b, Index e)
      {
        for (Index k = b; k < e; ++k)
        {
          this->Previous[static_cast<size_t>(k)] =
            this->Phi(this->Phi.nodeIndex(this->ReinitBand[static_cast<size_t>(k)]));
        }
      });
    // (4.22)/(4.24); on slabs the feet beyond the window are interpolated by their owners.
    const bool distributed = this->Slab.distributed();
    SLTK_RETURN_IF_ERROR(this->Slab.agree(levelSetStepValues<Interp, D>(
      this->Ctx, this->Phi, this->Dist, this->Band, step, this->StepScratch, distributed ? &this->Far : nullptr)));
    if (distributed)
    {
      double feet = 0.0;
      SLTK_RETURN_IF_ERROR(resolveFarFeet<Interp>(
        this->Phi, this->Far, this->Slab.whole(), this->Slab.boundaries(), this->Slab.comm(), feet));
      SLTK_RETURN_IF_ERROR(this->Slab.agree(finishFarNodes(this->Far, this->StepScratch)));
      this->FarFeetCount += static_cast<Index>(feet);
    }
    storeLevelSetStep(this->Ctx, this->Phi, this->Band, this->StepScratch);
    this->Slab.exchange(this->Phi, ReinitEntryRows); // what the reinitialisation reads; every ghost row after the cut
    return Status::ok();
  }

  Status reinitialise()
  {
    SLTK_RETURN_IF_ERROR(
      reinitialiseOn(this->Phi, this->ReinitBand, this->Slab, this->Options.Reinit, this->Ctx, &this->ReinitArrays));
    cutLevelSet(this->Phi, this->ReinitBand, this->Gamma, this->Ctx); // (1.49)
    this->Slab.exchange(this->Phi);
    this->Phi.fillGhosts(this->Ctx);
    filterBand(this->Phi, this->ReinitBand, this->Gamma, this->Ctx, this->Band); // (1.54)
    return Status::ok();
  }

  /// This rank's sums of eps_1 (4.34) between successive iterates (phi^n at
  /// the reinitialised nodes, the only ones that changed) and of Err_P (4.35)
  /// over the points of its owned cells, its band size and whether it was
  /// interrupted: one all-reduce.
  bool measure(IterationRecord& it, bool interrupted) const
  {
    const SlabPlan& s = this->Slab.slab();
    double sums[5] = { 0.0, 0.0,
      cloudErrorSum<D, Interp>(this->Phi, this->Points.cloud(), this->Ctx, s.Begin, s.End, this->Slab.rows()),
      static_cast<double>(this->Band.size()), interrupted ? 1.0 : 0.0 };
    // eps_1 of (4.34), summed in fixed chunks (ThreadPool.h: the same on any thread count)
    const Index size = static_cast<Index>(this->ReinitBand.size());
    sums[0] = this->Ctx.parallelSum(0, size,
      [&](Index b, Index e)
      {
        double sum = 0.0;
        for (Index k = b; k < e; ++k)
        {
          const size_t at = static_cast<size_t>(k);
          sum += std::fabs(this->Phi(this->Phi.nodeIndex(this->ReinitBand[at])) - this->Previous[at]);
        }
        return sum;
      });
    sums[1] = this->Ctx.parallelSum(0, size,
      [&](Index b, Index e)
      {
        double sum = 0.0;
        for (Index k = b; k < e; ++k)
        {
          sum += std::fabs(this->Previous[static_cast<size_t>(k)]);
        }
        return sum;
      });
    this->Slab.comm().allReduce(sums, 5, ReduceOp::Sum);
    it.Change = sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
    it.CloudError = sums[2] / static_cast<double>(this->Points.total());
    it.BandSize = static_cast<Index>(sums[3]);
    return sums[4] > 0.0;
  }

  /// Gives the band's single-node specks (IsolatedNodes.h) their neighbours'
  /// mean, ghost rows exchanged after; returns their count over every rank.
  Index mergeIsolatedNodes()
  {
    std::vector<NodeChange> changes;
    findIsolatedNodes(this->Phi, this->Band, changes);
    applyNodeChanges(this->Phi, changes);
    this->Slab.exchange(this->Phi);
    this->Phi.fillGhosts();
    return static_cast<Index>(this->Slab.sum(static_cast<double>(changes.size())));
  }

  void finish(RunRecord<D>& record, double far)
  {
    record.GhostRows = this->Slab.slab().Ghost;
    record.FarFeet = this->FarFeetCount;
    record.PointsHeld = this->Slab.comm().allReduce(std::int64_t(this->Points.held()), ReduceOp::Max);
    if (record.Iterations == 0)
    {
      this->Phi.fillGhosts();
      const SlabPlan& s = this->Slab.slab();
      record.CloudError = this->Slab.sum(cloudErrorSum<D, Interp>(
                            this->Phi, this->Points.cloud(), this->Ctx, s.Begin, s.End, this->Slab.rows())) /
        static_cast<double>(this->Points.total());
    }
    record.FarPoints = this->farFraction(far);
  }

  std::string describe() const { return {}; }

private:
  const RunPoints<D>& Points;
  const ReconstructionOptions& Options;
  const Context& Ctx;
  ExactDistanceCache<D>& Exact;
  const RunSlab<D>& Slab;
  GridField<D>& Phi;
  GridField<D>& Dist;
  const double Gamma;
  NodeList Band, ReinitBand, GhostBand;      // Band: the owned rows' B^n; GhostBand: the adjacent ghost rows'
  std::vector<double> StepScratch, Previous; // Previous: phi^n at ReinitBand, for eps_1 (4.34)
  ReinitWorkspace ReinitArrays;              // the reinitialisation's arrays, for every iteration of the run
  FarFeet<D> Far;
  Index FarFeetCount = 0;
};

} // namespace sltk
