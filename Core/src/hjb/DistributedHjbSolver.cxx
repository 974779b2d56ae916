// SPDX-License-Identifier: BSD-3-Clause
// The distributed HJB solver: slabs of the last axis with ghost rows exchanged
// after every step (DistributedHjbSolver.h).
#include "sltk/hjb/DistributedHjbSolver.h"

#include "ExpressionDiagnosis.h"
#include "ExpressionSolverOf.h"
#include "HjbExtents.h"
#include "sltk/grid/SlabExchange.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace sltk
{
namespace
{

/// max |f_D| along the last axis over every node, the sampled controls and t = 0, T/2, T.
double largestSpeed(const HjbExpressionSpec& spec, const CompiledHjbExpressions& compiled, const HjbGrid& grid)
{
  const int last = spec.Dimension - 1;
  const int controls = spec.Controls == ControlKind::None ? 0 : spec.ControlDimension;
  const auto samples = sampleControls(spec);
  const Index nodes = grid.Dims[0] * grid.Dims[1] * grid.Dims[2];
  double fastest = 0.0;
  double v[SlotCount] = {};
  for (Index k = 0; k < nodes; ++k)
  {
    Index rest = k;
    for (int a = 0; a < 3; ++a)
    {
      const Index i = rest % grid.Dims[a];
      rest /= grid.Dims[a];
      v[SlotX + a] = a < spec.Dimension ? grid.Origin[a] + static_cast<double>(i) * grid.Spacing[a] : 0.0;
    }
    for (const double t : { 0.0, 0.5 * spec.FinalTime, spec.FinalTime })
    {
      v[SlotT] = t;
      for (const auto& a : samples)
      {
        for (int j = 0; j < 3; ++j)
        {
          v[SlotA + j] = j < controls ? a[static_cast<size_t>(j)] : 0.0;
        }
        const double speed = std::fabs(compiled.Dynamics[static_cast<size_t>(last)].evaluate(v));
        fastest = std::isfinite(speed) ? std::max(fastest, speed) : fastest;
      }
    }
  }
  return fastest;
}

class DistributedSolver final : public HjbSolver
{
public:
  DistributedSolver(std::unique_ptr<HjbSolver> inner, const Communicator& comm, HjbGrid whole, ExactSolution exact,
    const SlabPlan& slab, bool reachable)
    : Inner(std::move(inner))
    , Comm(comm)
    , Whole(whole)
    , Exact(std::move(exact))
    , Slab(slab)
    , Reachable(reachable)
  {
  }

  const HjbGrid& grid() const override { return this->Whole; }
  double timeStep() const override { return this->Inner->timeStep(); }
  Index stepCount() const override { return this->Inner->stepCount(); }
  double startTime() const override { return this->Inner->startTime(); }
  Index stepsDone() const override { return this->Inner->stepsDone(); }
  void readValues(Index first, Index count, double* out) override { this->Inner->readValues(first, count, out); }
  void writeValues(Index first, Index count, const double* values) override
  {
    this->Inner->writeValues(first, count, values);
  }

  Status advanceTo(double t, const Context& ctx) override
  {
    const double dt = this->timeStep();
    if (t < this->time() - 1e-9 * dt)
    {
      SLTK_RETURN_IF_ERROR(this->Comm.agree(this->Inner->advanceTo(this->startTime(), ctx))); // back to u^0
    }
    // u^0 is built on the first call (the serial solver's advanceTo does it), even when no step is asked for.
    SLTK_RETURN_IF_ERROR(this->Comm.agree(this->Inner->advanceTo(this->time(), ctx)));
    if (this->Slab.Periodic && this->stepsDone() == 0)
    {
      // The wrapped ghost rows' u^0 came from coordinates a period away (the same value to rounding):
      // the owners' values instead, so that the first step reads what one rank's does.
      this->exchange();
    }
    Index target = this->stepsDone();
    while (target < this->stepCount() && this->startTime() + static_cast<double>(target + 1) * dt <= t + 1e-9 * dt)
    {
      ++target;
    }
    while (this->stepsDone() < target)
    {
      const double next = this->startTime() + static_cast<double>(this->stepsDone() + 1) * dt;
      SLTK_RETURN_IF_ERROR(this->Comm.agree(this->Inner->advanceTo(next, ctx)));
      this->exchange();
    }
    return Status::ok();
  }

  void result(HjbRunResult& out) const override { this->resultBlock(wholeExtent(this->Whole), out); }

  double evaluationsPerNode() const override { return this->Inner->evaluationsPerNode(); }
  int ranks() const override { return this->Comm.size(); }

  void resultBlock(const HjbExtent& extent, HjbRunResult& out) const override
  {
    out = HjbRunResult{};
    out.Grid = this->Whole;
    out.Block = intersectExtents(extent, wholeExtent(this->Whole));
    out.FinalTime = this->time();
    out.Steps = this->stepsDone();
    // The work statistic of every node update done, the ghost rows' included (so not bitwise one rank's).
    const double localNodes = static_cast<double>(extentNodes(this->slabExtent()));
    double work[2] = { this->Inner->evaluationsPerNode() * localNodes, localNodes };
    this->Comm.allReduce(work, 2, ReduceOp::Sum);
    out.EvaluationsPerNode = work[0] / work[1];
    if (this->Exact && out.Steps > 0)
    {
      this->errors(out);
    }
    this->redistribute(out);
  }

private:
  /// The nodes rank q owns: the whole grid's, its rows [rows q / P, rows (q + 1) / P) of the last axis.
  HjbExtent ownedExtent(int q) const
  {
    HjbExtent e = wholeExtent(this->Whole);
    const int last = this->Whole.Dimension - 1;
    const Index rows = this->Whole.Dims[static_cast<size_t>(last)], size = this->Comm.size();
    e[2 * last] = evenSlabBegin(rows, q, size);
    e[2 * last + 1] = evenSlabBegin(rows, q + 1, size) - 1;
    return e;
  }

  /// The nodes of this rank's slab, ghost rows included (local.Value's layout).
  HjbExtent slabExtent() const
  {
    HjbExtent e = wholeExtent(this->Whole);
    const int last = this->Whole.Dimension - 1;
    e[2 * last] = this->Slab.First;
    e[2 * last + 1] = this->Slab.Stop - 1;
    return e;
  }

  /// Copies the nodes of `box` (owned by this rank) from the slab's state to
  /// `to`, the nodes of `toExtent`, one row of x at a time (no copy of the slab).
  void readOwned(const HjbExtent& box, double* to, const HjbExtent& toExtent) const
  {
    const HjbExtent slab = this->slabExtent();
    const Index nx = slab[1] - slab[0] + 1, ny = slab[3] - slab[2] + 1, row = box[1] - box[0] + 1;
    const Index toNx = toExtent[1] - toExtent[0] + 1, toNy = toExtent[3] - toExtent[2] + 1;
    for (Index k = box[4]; k <= box[5]; ++k)
    {
      for (Index j = box[2]; j <= box[3]; ++j)
      {
        const Index at = (box[0] - toExtent[0]) + toNx * ((j - toExtent[2]) + toNy * (k - toExtent[4]));
        this->Inner->readValues((box[0] - slab[0]) + nx * ((j - slab[2]) + ny * (k - slab[4])), row, to + at);
      }
    }
  }

  /// Every rank's block from the ranks that own its nodes: P - 1 pairwise
  /// exchanges (d = 1 .. P-1: send to rank + d, receive from rank - d), each
  /// of the nodes one owns and the other asks for (none when the boxes do not
  /// meet). The reachable set (3.40), when kept, goes along (a copy of the slab).
  void redistribute(HjbRunResult& out) const
  {
    const int size = this->Comm.size(), rank = this->Comm.rank();
    std::vector<HjbExtent> asked(static_cast<size_t>(size));
    this->Comm.allGather(out.Block.data(), sizeof(HjbExtent), asked.data());
    HjbRunResult local;
    if (this->Reachable)
    {
      this->Inner->result(local);
    }
    const int fields = this->Reachable ? 2 : 1;
    const Index blockNodes = extentNodes(out.Block);
    out.Value.assign(static_cast<size_t>(blockNodes), 0.0);
    out.ReachTime.assign(this->Reachable ? static_cast<size_t>(blockNodes) : 0, 0.0);
    const HjbExtent slab = this->slabExtent();
    std::vector<double> send, receive;
    // d = 0: this rank's own nodes of its block, straight from the slab (no message, no buffer).
    const HjbExtent own = intersectExtents(this->ownedExtent(rank), out.Block);
    if (extentNodes(own) > 0)
    {
      this->readOwned(own, out.Value.data(), out.Block);
      if (this->Reachable)
      {
        copyExtent(local.ReachTime.data(), slab, out.ReachTime.data(), out.Block, own);
      }
    }
    for (int d = 1; d < size; ++d)
    {
      const int to = (rank + d) % size, from = (rank - d + size) % size;
      const HjbExtent sent = intersectExtents(this->ownedExtent(rank), asked[static_cast<size_t>(to)]);
      const HjbExtent received = intersectExtents(this->ownedExtent(from), out.Block);
      const Index sentNodes = extentNodes(sent), receivedNodes = extentNodes(received);
      send.resize(static_cast<size_t>(fields * sentNodes));
      receive.resize(static_cast<size_t>(fields * receivedNodes));
      if (sentNodes > 0)
      {
        this->readOwned(sent, send.data(), sent);
      }
      if (this->Reachable)
      {
        copyExtent(local.ReachTime.data(), slab, send.data() + sentNodes, sent, sent);
      }
      this->Comm.sendReceive(
        send.data(), send.size() * sizeof(double), to, receive.data(), receive.size() * sizeof(double), from);
      copyExtent(receive.data(), received, out.Value.data(), out.Block, received);
      if (this->Reachable)
      {
        copyExtent(receive.data() + receivedNodes, received, out.ReachTime.data(), out.Block, received);
      }
    }
  }

  /// L1 and max errors over the owned nodes, reduced over the ranks (the
  /// serial solver's sums, HjbError.h, up to the order of the additions).
  void errors(HjbRunResult& out) const
  {
    const HjbGrid& g = this->Whole;
    const HjbExtent owned = this->ownedExtent(this->Comm.rank());
    std::vector<double> row(static_cast<size_t>(owned[1] - owned[0] + 1));
    double x[3] = { 0.0, 0.0, 0.0 };
    double sum = 0.0, worst = 0.0, cell = 1.0;
    bool flagged = false;
    double notFinite[4] = { 0.0, 0.0, 0.0, 0.0 }; // x, y, z and the exact value there
    for (int a = 0; a < g.Dimension; ++a)
    {
      cell *= g.Spacing[a];
    }
    for (Index k = owned[4]; k <= owned[5]; ++k)
    {
      for (Index j = owned[2]; j <= owned[3]; ++j)
      {
        const HjbExtent line{ owned[0], owned[1], j, j, k, k };
        this->readOwned(line, row.data(), line);
        for (Index i = owned[0]; i <= owned[1]; ++i)
        {
          const Index ijk[3] = { i, j, k };
          for (int a = 0; a < g.Dimension; ++a)
          {
            x[a] = g.Origin[a] + static_cast<double>(ijk[a]) * g.Spacing[a];
          }
          const double exact = this->Exact(out.FinalTime, x);
          if (!std::isfinite(exact) && !flagged)
          {
            flagged = true;
            std::copy(x, x + 3, notFinite);
            notFinite[3] = exact;
          }
          const double e = std::fabs(row[static_cast<size_t>(i - owned[0])] - exact);
          sum += e;
          worst = std::max(worst, e);
        }
      }
    }
    out.L1Error = cell * this->Comm.allReduce(sum, ReduceOp::Sum);
    out.LinfError = this->Comm.allReduce(worst, ReduceOp::Max);
    // The lowest flagged rank's first non-finite exact value (the serial solver reports its first node).
    std::vector<double> flags(static_cast<size_t>(5 * this->Comm.size()));
    const double mine[5] = { flagged ? 1.0 : 0.0, notFinite[0], notFinite[1], notFinite[2], notFinite[3] };
    this->Comm.allGather(mine, sizeof(mine), flags.data());
    for (size_t r = 0; r < flags.size(); r += 5)
    {
      if (flags[r] > 0.0)
      {
        out.ExactNotFiniteAt.assign(flags.begin() + static_cast<std::ptrdiff_t>(r + 1),
          flags.begin() + static_cast<std::ptrdiff_t>(r + 1 + g.Dimension));
        out.ExactNotFiniteAt.push_back(flags[r + 4]);
        break;
      }
    }
  }

  /// The first G owned rows go down (rank - 1), the last G up (rank + 1); the ghost rows come back.
  void exchange()
  {
    const Index rowNodes = extentNodes(this->slabExtent()) / this->Slab.windowRows();
    exchangeSlabRows<double>(
      this->Slab, rowNodes, this->Comm,
      [&](Index first, Index rows, double* to) { this->Inner->readValues(first * rowNodes, rows * rowNodes, to); },
      [&](Index first, Index rows, const double* from)
      { this->Inner->writeValues(first * rowNodes, rows * rowNodes, from); });
  }

  std::unique_ptr<HjbSolver> Inner;
  const Communicator& Comm;
  HjbGrid Whole;
  ExactSolution Exact; ///< empty: none known
  SlabPlan Slab;       ///< this rank's rows of the last axis
  bool Reachable;      ///< the reachable set (3.40) is kept
};
} // namespace

Status planSlabs(const HjbGrid& grid, double speed, double dt, const Communicator& comm, SlabPlan& plan, bool periodic)
{
  const int last = grid.Dimension - 1;
  const double reach = 1.25 * speed * dt / grid.Spacing[static_cast<size_t>(last)];
  return planSlab(grid.Dims[static_cast<size_t>(last)], static_cast<Index>(std::ceil(reach)) + HjbStencilRows,
    comm.rank(), comm.size(), "the feet reach that far in one step", plan, periodic);
}

std::unique_ptr<HjbSolver> makeDistributedSolver(std::unique_ptr<HjbSolver> window, const Communicator& comm,
  const HjbGrid& whole, ExactSolution exact, const SlabPlan& slab, bool reachable)
{
  return std::make_unique<DistributedSolver>(std::move(window), comm, whole, std::move(exact), slab, reachable);
}

Status makeDistributedExpressionSolver(
  const HjbExpressionSpec& spec, const Communicator& comm, std::unique_ptr<HjbSolver>& solver)
{
  solver.reset();
  if (comm.size() == 1)
  {
    return makeExpressionSolver(spec, solver);
  }
  // Checked on every rank alike (the same spec), so every rank fails or none; the whole grid is planned, not
  // allocated (each rank's memory check is its slab's, in makeExpressionSolver below).
  auto compiled = std::make_shared<CompiledHjbExpressions>();
  HjbGrid grid;
  double dt = 0.0;
  SLTK_RETURN_IF_ERROR(planExpressionSolve(spec, *compiled, grid, dt));
  const int last = spec.Dimension - 1;
  const bool periodic = spec.Bounds[static_cast<size_t>(last)] == Boundary::Periodic;
  SlabPlan slab;
  SLTK_RETURN_IF_ERROR(planSlabs(grid, largestSpeed(spec, *compiled, grid), dt, comm, slab, periodic));
  const Index rows = grid.Dims[static_cast<size_t>(last)], first = slab.First, stop = slab.Stop;
  HjbExpressionSpec local = spec; // the slab: the whole grid's coordinates, spacing and time steps, bitwise
  local.WindowFirst[static_cast<size_t>(last)] = first;
  local.WindowNodes[static_cast<size_t>(last)] = stop - first;
  if (!spec.InitialValues.empty())
  {
    // Row by row: a periodic slab's ghost rows past either end are the other end's rows.
    const Index rowNodes = static_cast<Index>(spec.InitialValues.size()) / rows;
    local.InitialValues.clear();
    local.InitialValues.reserve(static_cast<size_t>((stop - first) * rowNodes));
    for (Index row = first; row < stop; ++row)
    {
      const auto from = spec.InitialValues.begin() + static_cast<std::ptrdiff_t>((row + rows) % rows * rowNodes);
      local.InitialValues.insert(local.InitialValues.end(), from, from + static_cast<std::ptrdiff_t>(rowNodes));
    }
  }
  std::unique_ptr<HjbSolver> inner;
  SLTK_RETURN_IF_ERROR(comm.agree(makeExpressionSolver(local, inner)));
  ExactSolution exact;
  if (compiled->HasExact)
  {
    exact = [compiled](double t, const double* x)
    {
      double v[SlotCount] = {};
      v[SlotT] = t;
      std::copy(x, x + 3, v + SlotX);
      return compiled->Exact.evaluate(v);
    };
  }
  solver = makeDistributedSolver(std::move(inner), comm, grid, std::move(exact), slab,
    spec.ReachableSet || compiled->HasObstacle); // as makeExpressionSolver() decides
  return Status::ok();
}

} // namespace sltk
