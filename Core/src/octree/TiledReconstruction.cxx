// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/octree/TiledReconstruction.h"

#include "../recon/RunLoop.h"
#include "../recon/SlabRuns.h"
#include "TiledBand.h"
#include "TiledTransfer.h"
#include "sltk/grid/SlabExchange.h"
#include "sltk/recon/InsideComponents.h"
#include "sltk/recon/ReconstructionInterpolator.h"
#include "sltk/recon/RunIterations.h"

#include <algorithm>
#include <chrono>
#include <sstream>

namespace sltk
{

namespace
{
using namespace octree;

/// The run's storage record: tiles and node counts over every rank (each
/// tile counted by its owner; AddedTiles, FreedTiles, PeakTiles and
/// ExactDistances summed over the ranks), the bytes this rank holds.
template <int D>
void recordStorage(const TiledField<D>& field, int run, const TiledRunRecord& iterations,
  const TileDistribution<D>& distribution, std::vector<TiledRunRecord>& storage)
{
  TiledRunRecord r = iterations;
  r.Run = run;
  const auto held = distribution.storageCounts(field);
  r.Tiles = held.Tiles;
  r.StoredNodes = r.Tiles * TiledField<D>::Nodes;
  r.Leaves = held.Leaves;
  r.LargestRankLeaves = held.LargestRankLeaves;
  r.UniformNodes = field.grid().nodeCount();
  r.Bytes = field.bytes();
  std::int64_t counts[4] = { r.AddedTiles, r.FreedTiles, r.PeakTiles, r.ExactDistances };
  distribution.comm().allReduce(counts, 4, ReduceOp::Sum);
  r.AddedTiles = counts[0];
  r.FreedTiles = counts[1];
  r.PeakTiles = counts[2];
  r.ExactDistances = counts[3];
  storage.push_back(r);
}

/// The transferred level set reinitialised on its band before run `run`'s
/// iterations; the reinitialiser's per-node arrays are freed on return (they
/// were as large as the tiles on the bunny's run 3).
template <int D>
Status reinitialiseTransferred(const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field,
  TileDistribution<D>& distribution)
{
  std::vector<std::int32_t> band;
  bandTiles(field, ctx, band);
  Index added = 0;
  std::vector<std::int64_t> changes;
  SLTK_RETURN_IF_ERROR(distribution.agree(extendBand(
    band, bandReachOf(field, band, plan.Options, ctx), plan.Options, run, field, added, distribution, changes)));
  distribution.shareChanges(field, changes, NothingToForget); // only new tiles: the band's ids stay
  TiledReinitialiser<D> reinit;
  reinit.markBand(field, band, plan.Options.ReinitDilation, ctx, distribution);
  return distribution.agree(reinit.run(field, plan.Options.Reinit, ctx, distribution));
}

/// The nodes of a tiled result for insideComponents(): every line, the nodes of this
/// rank's slots (their phi, or the slot's side), runs broken at the tiles' edges so that
/// a neighbour's run lies in one tile, held here as a ghost (TileDistribution.h).
template <int D>
class TiledNodes
{
public:
  TiledNodes(const TiledField<D>& field, const std::vector<std::int32_t>& owners, int rank)
    : Field(field)
    , Owners(owners)
    , Rank(rank)
  {
  }
  const std::array<Index, D>& dims() const { return this->Field.grid().Dims; }
  void lines(Index& first, Index& end) const
  {
    first = 0;
    end = this->Field.grid().nodeCount() / this->dims()[0];
  }
  int owner(const std::array<Index, D>& i) const
  {
    std::array<Index, D> t{};
    for (int a = 0; a < D; ++a)
    {
      t[a] = i[a] >> TileBits;
    }
    return this->Owners.empty() ? this->Rank : this->Owners[static_cast<size_t>(this->Field.slotIndex(t))];
  }
  bool inside(const std::array<Index, D>& i) const { return this->Field.value(i) < 0.0; }
  Index period() const { return TileEdge; }

private:
  const TiledField<D>& Field;
  const std::vector<std::int32_t>& Owners;
  const int Rank;
};

/// The tiled storage of the runs (recon/RunLoop.h's `Runs`): run 1 on the
/// uniform grid, split in slabs over the ranks (recon/SlabRuns.h), then
/// gathered whole on every rank for the transfer; runs >= 2 on tiles around
/// the front (TiledBand.h), each run's tiles built from the previous run's
/// level set, which is then freed (the memory follows one run's surface).
template <int D, class Interp>
class TiledRuns
{
public:
  TiledRuns(const ReconstructionPlan<D>& plan, const ReconstructionOptions& options,
    const std::vector<GridSpec<D>>& grids, const Context& ctx, const Communicator& comm,
    TiledReconstructionResult<D>& out)
    : Plan(plan)
    , Options(options)
    , Grids(grids)
    , Ctx(ctx)
    , First(plan, options, grids, ctx, comm)
    , Distribution(comm)
    , Out(out)
  {
  }

  /// The ranks the runs are split over.
  const Communicator& comm() const { return this->Distribution.comm(); }

  Status setUp(int run, double outsideFactor)
  {
    if (run == 1)
    {
      return this->First.setUp(1, outsideFactor);
    }
    const auto setup = std::chrono::steady_clock::now();
    const FarPointSeeds<D>& seeds = run == 2 ? this->First.seeds() : this->Seeds;
    this->Field = TiledField<D>{};
    SLTK_RETURN_IF_ERROR(transferToTiles(this->Previous, this->PreviousGamma, seeds,
      this->Grids[static_cast<size_t>(run - 1)], this->Plan, run, this->Ctx, this->Field, this->Distribution));
    SLTK_RETURN_IF_ERROR(reinitialiseTransferred(this->Plan, run, this->Ctx, this->Field, this->Distribution));
    std::ostringstream log;
    log << "run " << run << " (tiled): " << this->Distribution.globalTileCount(this->Field) << " tiles of "
        << this->Field.slotCount() << " (" << this->Field.bytes() / 1048576.0 << " MB on this rank), set up in "
        << detail::secondsSince(setup) << " s";
    if (this->Options.SeedFarPoints)
    {
      log << ", " << seeds.Centres.size() << " point(s) run " << run - 1 << " left outside seeded back";
    }
    this->Ctx.logger().log(LogLevel::Info, log.str());
    this->Dense = GridField<D>{}; // the previous run is no longer needed
    this->Last = TiledField<D>{};
    return Status::ok();
  }

  Status iterate(int run, ReconstructionResult<D>& records, bool& vanished)
  {
    if (run == 1)
    {
      return this->First.iterate(1, records, vanished);
    }
    TiledRunRecord storage;
    storage.PeakTiles = this->Field.tileCount(); // the transfer's and the setup reinitialisation's
    TiledBand<D, Interp> band(this->Plan, run, this->Ctx, this->Field, this->Distribution, storage);
    const Status status =
      iterateRun<D>(band, this->Options, run, this->Plan.CloudSpacing, this->Ctx, records, vanished);
    const bool ran = status.isOk() && !vanished;
    this->Seeds = seedsAfterRun<D>(band, this->Plan.CloudSpacing, this->Options, run, ran, this->Distribution.comm());
    records.MissedPlaces = missedPlacesAfterRun(band, *this->Plan.Locator, this->Plan.CloudSpacing, this->Options, run,
      ran, records.Runs, this->Distribution.comm());
    recordStorage(this->Field, run, storage, this->Distribution, this->Out.Storage);
    return status;
  }

  void advance(int run)
  {
    if (run == 1)
    {
      this->gatherFirstRun();
      return;
    }
    this->Last = std::move(this->Field);
    this->Previous.Dense = nullptr;
    this->Previous.Tiled = &this->Last;
    this->PreviousGamma = this->Last.gamma();
  }

  Status keepCurrent(int run, ReconstructionResult<D>&)
  {
    if (run == 1)
    {
      // One run: its uniform result, stored in tiles.
      this->gatherFirstRun();
      SLTK_RETURN_IF_ERROR(transferToTiles(this->Previous, this->PreviousGamma, FarPointSeeds<D>{}, this->Dense.spec(),
        this->Plan, 1, this->Ctx, this->Out.Field, this->Distribution));
      recordStorage(this->Out.Field, 1, TiledRunRecord{}, this->Distribution, this->Out.Storage);
    }
    else
    {
      this->Out.Field = std::move(this->Field);
    }
    this->Out.Owners = this->Distribution.owners();
    return Status::ok();
  }

  void keepFailed(int, ReconstructionResult<D>&) {}

  /// The pieces of the kept result (InsideComponents.h).
  std::int64_t pieces(const ReconstructionResult<D>&) const
  {
    const Communicator& comm = this->Distribution.comm();
    return insideComponents<D>(TiledNodes<D>(this->Out.Field, this->Out.Owners, comm.rank()), comm);
  }

  Status keepPrevious(int run, ReconstructionResult<D>&)
  {
    return Status::numericalFailure("the octree storage no longer holds run " + std::to_string(run - 1) +
      " (each run's tiles are freed once the next run is set up): try a smaller eta in later runs (--schedule)");
  }

  /// Run 1's leaves (its nodes) and the most one rank owns, for its history rows.
  Index firstRunLeaves() const { return this->FirstRunLeaves; }
  Index firstRunLargestRankLeaves() const { return this->FirstRunLargestRankLeaves; }

private:
  /// Run 1's phi whole on every rank for the transfer, and its leaves.
  void gatherFirstRun()
  {
    ReconstructionResult<D> first;
    this->First.keepCurrent(1, first);
    const Communicator& comm = this->Distribution.comm();
    const GridSpec<D>& grid = first.WholeGrid;
    const Index nodes = grid.nodeCount();
    // Run 1 is uniform: every node is a leaf, and each rank owns its slab's rows.
    this->FirstRunLeaves = nodes;
    this->FirstRunLargestRankLeaves = comm.allReduce(
      static_cast<std::int64_t>((first.Slab.End - first.Slab.Begin) * (nodes / grid.Dims[D - 1])), ReduceOp::Max);
    this->Dense = this->Distribution.distributed()
      ? gatherSlabRows(first.SignedDistance, first.Slab, first.WholeGrid, first.SignedDistance.ghost(), comm)
      : std::move(first.SignedDistance);
    this->Dense.fillGhosts();
    this->Previous.Dense = &this->Dense;
    this->Previous.Tiled = nullptr;
    this->PreviousGamma = this->Plan.Options.GammaFactor * this->Dense.spec().Spacing[0];
  }

  const ReconstructionPlan<D>& Plan;
  const ReconstructionOptions& Options;
  const std::vector<GridSpec<D>>& Grids;
  const Context& Ctx;
  SlabRuns<D, Interp> First;
  TileDistribution<D> Distribution;
  TiledReconstructionResult<D>& Out;
  GridField<D> Dense;           // run 1's phi, whole on every rank, until run 2 is set up
  TiledField<D> Field, Last;    // this run's tiles; the previous run's until this one is set up
  PreviousLevelSet<D> Previous; // what the next run is transferred from
  FarPointSeeds<D> Seeds;       // what the last tiled run left outside, for the next
  double PreviousGamma = 0.0;
  Index FirstRunLeaves = 0, FirstRunLargestRankLeaves = 0;
};
} // namespace

template <int D>
Status reconstructTiled(
  const ReconstructionPlan<D>& plan, const Context& ctx, TiledReconstructionResult<D>& result, const Communicator& comm)
{
  result = TiledReconstructionResult<D>{};
  result.Box = plan.Box;
  if (plan.Options.ReinitDilation >= TileEdge)
  {
    return Status::invalidArgument("the octree reconstruction takes a reinitialisation dilation of at most " +
      std::to_string(TileEdge - 1) + " nodes (one tile), not " + std::to_string(plan.Options.ReinitDilation) +
      ": use a smaller dilation or the uniform version");
  }
  return reconstructWithRecoveries(plan, ctx, comm, result.Records,
    [&](const ReconstructionOptions& options, const std::vector<GridSpec<D>>& grids)
    {
      result.Field = TiledField<D>{};
      result.Storage.clear();
      result.Owners.clear();
      return withReconstructionInterpolator<D>(options,
        [&](auto tag)
        {
          TiledRuns<D, typename decltype(tag)::type> runs(plan, options, grids, ctx, comm, result);
          const Status status = runAlgorithm1(runs, plan, options, ctx, result.Records);
          for (IterationRecord& it : result.Records.History)
          {
            if (it.Run == 1) // run 1 is uniform: every node is a leaf
            {
              it.StoredNodes = it.Leaves = it.UniformNodes = runs.firstRunLeaves();
              it.LargestRankLeaves = runs.firstRunLargestRankLeaves();
            }
          }
          return status;
        });
    });
}

template <int D>
Index completeTiledDistances(const ReconstructionPlan<D>& plan, const Context& ctx, TiledField<D>& field,
  const std::vector<std::int32_t>& owners, int rank)
{
  return TiledDistances<D>::completeAll(
    field, *plan.Locator, ctx, [&](std::int32_t id) { return ownedBy(owners, field.tileSlot(id), rank); });
}

template <int D>
void gatherTiles(TiledReconstructionResult<D>& result, const Communicator& comm, int root)
{
  if (comm.size() == 1)
  {
    return;
  }
  TiledField<D>& field = result.Field;
  std::vector<std::vector<std::int32_t>> going(static_cast<size_t>(comm.size()));
  if (comm.rank() != root)
  {
    field.forEachTileInSlotOrder(
      [&](std::int32_t id)
      {
        if (result.Owners[static_cast<size_t>(field.tileSlot(id))] == comm.rank())
        {
          going[static_cast<size_t>(root)].push_back(id);
        }
      });
  }
  const std::vector<unsigned char> incoming = TileDistribution<D>::sendWholeTiles(field, going, comm);
  if (comm.rank() != root)
  {
    return;
  }
  TileDistribution<D>::storeWholeTiles(field, incoming);
  result.Owners.clear();
}

template <int D>
ReconstructionSummary summarize(const TiledReconstructionResult<D>& result, const std::array<double, 3>& frame)
{
  ReconstructionSummary summary = summarize(result.Records, frame);
  summary.OctreeStorage = true;
  for (size_t r = 0; r < summary.Runs.size(); ++r)
  {
    // Run 1 is uniform (its grid is the coarsest: a leaf per node; the largest rank's, its
    // slab's, from the history), but for a single run, which is then stored in tiles: every
    // tiled run has a storage record.
    const int run = static_cast<int>(r + 1);
    RunSummary& s = summary.Runs[r];
    s.UniformNodes = s.StoredNodes = s.Leaves = s.LargestRankLeaves = result.Records.Runs[r].Grid.nodeCount();
    for (const IterationRecord& it : result.Records.History)
    {
      s.LargestRankLeaves = it.Run == run ? it.LargestRankLeaves : s.LargestRankLeaves;
    }
    for (const TiledRunRecord& stored : result.Storage)
    {
      if (stored.Run == run)
      {
        s.StoredNodes = stored.StoredNodes;
        s.Leaves = stored.Leaves;
        s.LargestRankLeaves = stored.LargestRankLeaves;
      }
    }
  }
  return summary;
}

template Status reconstructTiled(
  const ReconstructionPlan<2>&, const Context&, TiledReconstructionResult<2>&, const Communicator&);
template ReconstructionSummary summarize(const TiledReconstructionResult<2>&, const std::array<double, 3>&);
template ReconstructionSummary summarize(const TiledReconstructionResult<3>&, const std::array<double, 3>&);
template void gatherTiles(TiledReconstructionResult<2>&, const Communicator&, int);
template void gatherTiles(TiledReconstructionResult<3>&, const Communicator&, int);
template Index completeTiledDistances(
  const ReconstructionPlan<2>&, const Context&, TiledField<2>&, const std::vector<std::int32_t>&, int);
template Index completeTiledDistances(
  const ReconstructionPlan<3>&, const Context&, TiledField<3>&, const std::vector<std::int32_t>&, int);
template Status reconstructTiled(
  const ReconstructionPlan<3>&, const Context&, TiledReconstructionResult<3>&, const Communicator&);

} // namespace sltk
