// SPDX-License-Identifier: GPL-2.0-or-later
#include "sltk/p4est/CloudForest.h"

#include "P4estSupport.h"

#include "sltk/cloud/LocalSpacing.h"
#include "sltk/cloud/PointLocator.h"
#include "sltk/exec/Memory.h"
#include "sltk/recon/CloudPreparation.h"

#include <p8est.h>
#include <p8est_connectivity.h>
#include <p8est_extended.h>
#include <p8est_ghost.h>

#include <algorithm>
#include <chrono>
#include <sstream>

namespace sltk
{
namespace p4est
{

static_assert(ForestRootLength == P8EST_ROOT_LEN, "ForestRootLength is p4est's root length");

namespace
{
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// p4est callbacks: the refinement flag lives in the quadrant's user data.
void clearFlag(p8est_t*, p4est_topidx_t, p8est_quadrant_t* q)
{
  *static_cast<int*>(q->p.user_data) = 0;
}

int isFlagged(p8est_t*, p4est_topidx_t, p8est_quadrant_t* q)
{
  return *static_cast<int*>(q->p.user_data);
}

Status checkOptions(const CloudForestOptions& o)
{
  if (o.MinimumLevel < 0 || o.MaximumLevel < o.MinimumLevel || o.MaximumLevel > MaxForestLevel)
  {
    std::ostringstream m;
    m << "octree levels MinimumLevel = " << o.MinimumLevel << ", MaximumLevel = " << o.MaximumLevel
      << ": need 0 <= MinimumLevel <= MaximumLevel <= " << MaxForestLevel;
    return Status::invalidArgument(m.str());
  }
  if (!(o.BandCells >= 0.0) || !(o.BandSpacings >= 0.0) || !(o.BandCells + o.BandSpacings > 0.0) ||
    !(o.Padding >= 0.0 && o.Padding <= 10.0) || o.DensityNeighbours < 1)
  {
    return Status::invalidArgument("octree band and padding out of range: need BandCells >= 0, BandSpacings >= 0 "
                                   "(not both 0), 0 <= Padding <= 10, DensityNeighbours >= 1");
  }
  return Status::ok();
}

/// The forest about to reach `leaves` leaves at `level`: refused when it
/// would not fit in the budget (or the memory available), naming the level
/// that fits.
Status checkMemory(double leaves, int level, const CloudForestOptions& o)
{
  const double budget = static_cast<double>(o.MemoryBudget ? o.MemoryBudget : availableMemoryBytes()); // 0: unknown
  const double need = leaves * ForestBytesPerLeaf;
  if (budget > 0.0 && need > budget)
  {
    std::ostringstream m;
    m.precision(3);
    m << "the octree would reach " << leaves << " leaves (" << need / 1048576.0 << " MB) at level " << level
      << ", more than the " << budget / 1048576.0 << " MB " << (o.MemoryBudget ? "budget" : "available")
      << ": use MaximumLevel <= " << level - 1 << " or a wider cell (or more memory)";
    return Status::outOfMemory(m.str());
  }
  return Status::ok();
}
} // namespace

struct CloudForest::Impl
{
  const Communicator* Comm = nullptr;
  CloudForestOptions Options;
  BrickGeometry Brick;
  UnitBox<3> Box;
  PointCloud<3> Cloud; ///< unit box, canonical order
  std::unique_ptr<const PointLocator<3>> Locator;
  double CloudSpacing = 0.0;
  std::vector<double> Sparsity; ///< rho(Q) per point of Cloud
  std::vector<std::array<int, 3>> TreePositions;
  CloudForestStats Stats;
  std::vector<ForestLeaf> Leaves;
  std::vector<ForestLeaf> Ghosts;

  p8est_connectivity_t* Connectivity = nullptr;
  p8est_t* Forest = nullptr;
  p8est_ghost_t* Ghost = nullptr;

  ~Impl()
  {
    if (this->Ghost)
    {
      p8est_ghost_destroy(this->Ghost);
    }
    if (this->Forest)
    {
      p8est_destroy(this->Forest);
    }
    if (this->Connectivity)
    {
      p8est_connectivity_destroy(this->Connectivity);
    }
  }

  std::array<double, 3> centre(int tree, const std::array<std::int32_t, 3>& coords, int level) const
  {
    const std::array<int, 3>& t = this->TreePositions[static_cast<size_t>(tree)];
    const double half = 0.5 * P8EST_QUADRANT_LEN(level);
    std::array<double, 3> x{};
    for (int a = 0; a < 3; ++a)
    {
      x[a] = this->Brick.Origin[a] + this->Brick.TreeEdge * (t[a] + (coords[a] + half) / P8EST_ROOT_LEN);
    }
    return x;
  }

  bool inBand(const std::array<double, 3>& x, double h) const
  {
    const auto hit = this->Locator->nearest(x);
    const double band = this->Options.BandCells * this->Brick.cellSize(this->Options.MaximumLevel) +
      this->Options.BandSpacings * this->Sparsity[static_cast<size_t>(hit.Index)] * this->CloudSpacing;
    return hit.Distance - 0.5 * std::sqrt(3.0) * h <= band;
  }

  Status prepare(const PointCloud<3>& localPoints, const Context& ctx);
  Status refine(MPI_Comm mpiComm, const Context& ctx);
  void collectLeaves(const Context& ctx);
  void buildGhosts();
};

Status CloudForest::Impl::prepare(const PointCloud<3>& localPoints, const Context& ctx)
{
  PointCloud<3> cloud;
  cloud.Points = this->Comm->allGatherV(localPoints.Points);
  SLTK_RETURN_IF_ERROR(validateCloud(cloud)); // before sorting: no NaN in the comparisons
  std::sort(cloud.Points.begin(), cloud.Points.end());
  CloudCleaningReport report;
  SLTK_RETURN_IF_ERROR(checkAndCleanCloud(cloud, this->Options.Cleaning, ctx, report));
  SLTK_RETURN_IF_ERROR(
    placeInUnitBox(std::move(cloud), ctx, this->Cloud, this->Box, this->Locator, this->CloudSpacing));
  SLTK_RETURN_IF_ERROR(sparsityFactors(*this->Locator, this->Options.DensityNeighbours, ctx, this->Sparsity));
  this->Stats.CloudPoints = this->Cloud.size();
  this->Brick = brickOver(boundingBox(this->Cloud), this->Options.Padding);
  this->Stats.UniformCells = this->Brick.uniformCells(this->Options.MaximumLevel);
  return Status::ok();
}

Status CloudForest::Impl::refine(MPI_Comm mpiComm, const Context& ctx)
{
  const CloudForestOptions& o = this->Options;
  SLTK_RETURN_IF_ERROR(this->Comm->agree(checkMemory(this->Brick.uniformCells(o.MinimumLevel), o.MinimumLevel, o)));
  this->Connectivity =
    p8est_connectivity_new_brick(this->Brick.Trees[0], this->Brick.Trees[1], this->Brick.Trees[2], 0, 0, 0);
  this->TreePositions.resize(static_cast<size_t>(this->Connectivity->num_trees));
  for (p4est_topidx_t t = 0; t < this->Connectivity->num_trees; ++t)
  {
    const double* v = this->Connectivity->vertices + 3 * this->Connectivity->tree_to_vertex[8 * t];
    this->TreePositions[static_cast<size_t>(t)] = { static_cast<int>(v[0]), static_cast<int>(v[1]),
      static_cast<int>(v[2]) };
  }
  // Uniform to MinimumLevel at creation (min_quadrants 0, fill_uniform 1).
  this->Forest = p8est_new_ext(mpiComm, this->Connectivity, 0, o.MinimumLevel, 1, sizeof(int), clearFlag, nullptr);
  for (int level = o.MinimumLevel; level < o.MaximumLevel; ++level)
  {
    // Leaves coarser than `level` were not in the band at their own level; only this level's are tested.
    std::vector<std::pair<int, p8est_quadrant_t*>> candidates;
    for (p4est_topidx_t t = this->Forest->first_local_tree; t <= this->Forest->last_local_tree; ++t)
    {
      p8est_tree_t* tree = p8est_tree_array_index(this->Forest->trees, t);
      for (size_t i = 0; i < tree->quadrants.elem_count; ++i)
      {
        p8est_quadrant_t* q = p8est_quadrant_array_index(&tree->quadrants, i);
        *static_cast<int*>(q->p.user_data) = 0;
        if (q->level == level)
        {
          candidates.emplace_back(static_cast<int>(t), q);
        }
      }
    }
    const double h = this->Brick.cellSize(level);
    ctx.parallelFor(0, static_cast<Index>(candidates.size()),
      [&](Index b, Index e)
      {
        for (Index i = b; i < e; ++i)
        {
          p8est_quadrant_t* q = candidates[static_cast<size_t>(i)].second;
          const auto x = this->centre(candidates[static_cast<size_t>(i)].first, { q->x, q->y, q->z }, level);
          *static_cast<int*>(q->p.user_data) = this->inBand(x, h) ? 1 : 0;
        }
      });
    std::int64_t flagged = 0;
    for (const auto& c : candidates)
    {
      flagged += *static_cast<int*>(c.second->p.user_data);
    }
    flagged = this->Comm->allReduce(flagged, ReduceOp::Sum);
    if (flagged == 0)
    {
      break;
    }
    const double next = static_cast<double>(this->Forest->global_num_quadrants) + 7.0 * static_cast<double>(flagged);
    SLTK_RETURN_IF_ERROR(this->Comm->agree(checkMemory(next, level + 1, o)));
    p8est_refine(this->Forest, 0, isFlagged, clearFlag);
    p8est_partition(this->Forest, 0, nullptr);
  }
  return Status::ok();
}

void CloudForest::Impl::collectLeaves(const Context& ctx)
{
  const int rank = this->Comm->rank();
  const std::int64_t first = static_cast<std::int64_t>(this->Forest->global_first_quadrant[rank]);
  this->Leaves.clear();
  this->Leaves.reserve(static_cast<size_t>(this->Forest->local_num_quadrants));
  for (p4est_topidx_t t = this->Forest->first_local_tree; t <= this->Forest->last_local_tree; ++t)
  {
    p8est_tree_t* tree = p8est_tree_array_index(this->Forest->trees, t);
    for (size_t i = 0; i < tree->quadrants.elem_count; ++i)
    {
      const p8est_quadrant_t* q = p8est_quadrant_array_index(&tree->quadrants, i);
      ForestLeaf leaf;
      leaf.GlobalIndex = first + static_cast<std::int64_t>(this->Leaves.size());
      leaf.Tree = static_cast<std::int32_t>(t);
      leaf.Level = q->level;
      leaf.Coords = { q->x, q->y, q->z };
      leaf.Owner = rank;
      this->Leaves.push_back(leaf);
    }
  }
  // Cell-centred distance to the cloud (5.1.2, 5.2.3), exact (see CloudForest.h).
  ctx.parallelFor(0, static_cast<Index>(this->Leaves.size()),
    [&](Index b, Index e)
    {
      for (Index i = b; i < e; ++i)
      {
        ForestLeaf& leaf = this->Leaves[static_cast<size_t>(i)];
        leaf.Distance = this->Locator->nearest(this->centre(leaf.Tree, leaf.Coords, leaf.Level)).Distance;
      }
    });
  std::int64_t finest = 0;
  for (const ForestLeaf& leaf : this->Leaves)
  {
    finest += leaf.Level == this->Options.MaximumLevel ? 1 : 0;
  }
  this->Stats.LeavesAtMaximumLevel = this->Comm->allReduce(finest, ReduceOp::Sum);
  this->Stats.LocalLeaves = static_cast<std::int64_t>(this->Leaves.size());
  this->Stats.GlobalLeaves = static_cast<std::int64_t>(this->Forest->global_num_quadrants);
}

void CloudForest::Impl::buildGhosts()
{
  this->Ghost = p8est_ghost_new(this->Forest, P8EST_CONNECT_FULL);
  const size_t count = this->Ghost->ghosts.elem_count;
  this->Ghosts.assign(count, ForestLeaf{});
  int owner = 0;
  for (size_t g = 0; g < count; ++g)
  {
    while (static_cast<p4est_locidx_t>(g) >= this->Ghost->proc_offsets[owner + 1])
    {
      ++owner;
    }
    const p8est_quadrant_t* q = p8est_quadrant_array_index(&this->Ghost->ghosts, g);
    ForestLeaf& leaf = this->Ghosts[g];
    leaf.GlobalIndex = static_cast<std::int64_t>(this->Forest->global_first_quadrant[owner]) + q->p.piggy3.local_num;
    leaf.Tree = q->p.piggy3.which_tree;
    leaf.Level = q->level;
    leaf.Coords = { q->x, q->y, q->z };
    leaf.Owner = owner;
  }
  // The owners' distances: one exchange over the mirrors (leaves others see as ghosts).
  std::vector<void*> mirrorData(this->Ghost->mirrors.elem_count);
  for (size_t m = 0; m < mirrorData.size(); ++m)
  {
    const p8est_quadrant_t* q = p8est_quadrant_array_index(&this->Ghost->mirrors, m);
    mirrorData[m] = &this->Leaves[static_cast<size_t>(q->p.piggy3.local_num)].Distance;
  }
  std::vector<double> ghostData(count);
  p8est_ghost_exchange_custom(this->Forest, this->Ghost, sizeof(double), mirrorData.data(), ghostData.data());
  for (size_t g = 0; g < count; ++g)
  {
    this->Ghosts[g].Distance = ghostData[g];
  }
  this->Stats.GhostLeaves = static_cast<std::int64_t>(count);
}

CloudForest::CloudForest(std::unique_ptr<Impl> impl)
  : P(std::move(impl))
{
}

CloudForest::~CloudForest() = default;

Status CloudForest::build(const Communicator& comm, const PointCloud<3>& localPoints, const CloudForestOptions& options,
  const Context& ctx, std::unique_ptr<CloudForest>& forest)
{
  forest.reset();
  MPI_Comm mpiComm = MPI_COMM_NULL;
  SLTK_RETURN_IF_ERROR(comm.agree(checkOptions(options)));
  SLTK_RETURN_IF_ERROR(comm.agree(p4estCommunicator(comm, mpiComm)));
  auto impl = std::make_unique<Impl>();
  impl->Comm = &comm;
  impl->Options = options;
  auto start = Clock::now();
  SLTK_RETURN_IF_ERROR(comm.agree(impl->prepare(localPoints, ctx)));
  impl->Stats.PrepareSeconds = secondsSince(start);
  start = Clock::now();
  SLTK_RETURN_IF_ERROR(impl->refine(mpiComm, ctx));
  impl->Stats.RefineSeconds = secondsSince(start);
  start = Clock::now();
  p8est_balance(impl->Forest, P8EST_CONNECT_FULL, clearFlag); // 2:1 over faces, edges and corners (5.1.3)
  p8est_partition(impl->Forest, 0, nullptr);
  impl->Stats.BalanceSeconds = secondsSince(start);
  start = Clock::now();
  impl->collectLeaves(ctx);
  impl->Stats.DistanceSeconds = secondsSince(start);
  start = Clock::now();
  impl->buildGhosts();
  impl->Stats.GhostSeconds = secondsSince(start);
  forest.reset(new CloudForest(std::move(impl)));
  return Status::ok();
}

const CloudForestOptions& CloudForest::options() const
{
  return this->P->Options;
}

const BrickGeometry& CloudForest::brick() const
{
  return this->P->Brick;
}

const UnitBox<3>& CloudForest::unitBox() const
{
  return this->P->Box;
}

double CloudForest::cloudSpacing() const
{
  return this->P->CloudSpacing;
}

const CloudForestStats& CloudForest::stats() const
{
  return this->P->Stats;
}

int CloudForest::rank() const
{
  return this->P->Comm->rank();
}

int CloudForest::ranks() const
{
  return this->P->Comm->size();
}

const std::vector<ForestLeaf>& CloudForest::leaves() const
{
  return this->P->Leaves;
}

const std::vector<ForestLeaf>& CloudForest::ghosts() const
{
  return this->P->Ghosts;
}

std::array<double, 3> CloudForest::centre(const ForestLeaf& leaf) const
{
  return this->P->centre(leaf.Tree, leaf.Coords, leaf.Level);
}

std::array<int, 3> CloudForest::treePosition(int tree) const
{
  return this->P->TreePositions[static_cast<size_t>(tree)];
}

bool CloudForest::inBand(const std::array<double, 3>& x, double h) const
{
  return this->P->inBand(x, h);
}

std::vector<ForestLeaf> CloudForest::gather() const
{
  // p4est's partition is contiguous in Morton order: rank order is global order.
  return this->P->Comm->allGatherV(this->P->Leaves);
}

} // namespace p4est
} // namespace sltk
