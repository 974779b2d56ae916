// SPDX-License-Identifier: BSD-3-Clause
// makeDistributedExpressionSolver(): slabs of the last axis with ghost rows
// exchanged after every step (DistributedHjbSolver.h).
#include "sltk/hjb/DistributedHjbSolver.h"

#include "ExpressionDiagnosis.h"
#include "ExpressionSolverOf.h"

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
  DistributedSolver(std::unique_ptr<HjbSolver> inner, const Communicator& comm, HjbGrid whole,
    SharedHjbExpressions compiled, Index first, Index begin, Index end, Index ghost)
    : Inner(std::move(inner))
    , Comm(comm)
    , Whole(whole)
    , Compiled(std::move(compiled))
    , First(first)
    , Begin(begin)
    , End(end)
    , Ghost(ghost)
  {
    const int last = whole.Dimension - 1;
    for (int a = 0; a < last; ++a)
    {
      this->RowNodes *= whole.Dims[a];
    }
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

  void result(HjbRunResult& out) const override
  {
    HjbRunResult local;
    this->Inner->result(local);
    out = HjbRunResult{};
    out.Grid = this->Whole;
    out.FinalTime = local.FinalTime;
    out.Steps = local.Steps;
    // The work statistic of every node update done, the ghost rows' included (so not bitwise one rank's).
    const double localNodes = static_cast<double>(local.Value.size());
    double work[2] = { local.EvaluationsPerNode * localNodes, localNodes };
    this->Comm.allReduce(work, 2, ReduceOp::Sum);
    out.EvaluationsPerNode = work[0] / work[1];
    out.Value = this->gatherOwned(local.Value);
    if (!local.ReachTime.empty())
    {
      out.ReachTime = this->gatherOwned(local.ReachTime);
    }
    if (this->Compiled->HasExact && out.Steps > 0)
    {
      this->errors(out);
    }
  }

private:
  /// Owned rows of a local field (x fastest), gathered in rank order: the whole grid's values.
  std::vector<double> gatherOwned(const std::vector<double>& local) const
  {
    const auto from = local.begin() + static_cast<std::ptrdiff_t>((this->Begin - this->First) * this->RowNodes);
    const std::vector<double> owned(
      from, from + static_cast<std::ptrdiff_t>((this->End - this->Begin) * this->RowNodes));
    return this->Comm.allGatherV(owned);
  }

  /// L1 and max errors over the whole grid, every rank alike (the serial solver's sums, HjbError.h).
  void errors(HjbRunResult& out) const
  {
    const HjbGrid& g = this->Whole;
    double v[SlotCount] = {};
    v[SlotT] = out.FinalTime;
    double sum = 0.0, worst = 0.0, cell = 1.0;
    for (int a = 0; a < g.Dimension; ++a)
    {
      cell *= g.Spacing[a];
    }
    for (size_t k = 0; k < out.Value.size(); ++k)
    {
      Index rest = static_cast<Index>(k);
      for (int a = 0; a < 3; ++a)
      {
        const Index i = rest % g.Dims[a];
        rest /= g.Dims[a];
        v[SlotX + a] = a < g.Dimension ? g.Origin[a] + static_cast<double>(i) * g.Spacing[a] : 0.0;
      }
      const double exact = this->Compiled->Exact.evaluate(v);
      if (!std::isfinite(exact) && out.ExactNotFiniteAt.empty())
      {
        out.ExactNotFiniteAt.assign(v + SlotX, v + SlotX + g.Dimension);
        out.ExactNotFiniteAt.push_back(exact);
      }
      sum += std::fabs(out.Value[k] - exact);
      worst = std::max(worst, std::fabs(out.Value[k] - exact));
    }
    out.L1Error = cell * sum;
    out.LinfError = worst;
  }

  /// The first G owned rows go down (rank - 1), the last G up (rank + 1); the ghost rows come back.
  void exchange()
  {
    const int rank = this->Comm.rank();
    const int size = this->Comm.size();
    const int below = rank > 0 ? rank - 1 : -1;
    const int above = rank + 1 < size ? rank + 1 : -1;
    const Index count = this->Ghost * this->RowNodes;
    const size_t bytes = static_cast<size_t>(count) * sizeof(double);
    this->Send.resize(static_cast<size_t>(count));
    this->Receive.resize(static_cast<size_t>(count));
    const Index ownedFirst = (this->Begin - this->First) * this->RowNodes; // local node numbers
    const Index ownedEnd = (this->End - this->First) * this->RowNodes;
    // Down: my first owned rows to `below`, `above`'s into my upper ghost rows.
    if (below >= 0)
    {
      this->Inner->readValues(ownedFirst, count, this->Send.data());
    }
    this->Comm.sendReceive(
      this->Send.data(), below >= 0 ? bytes : 0, below, this->Receive.data(), above >= 0 ? bytes : 0, above);
    if (above >= 0)
    {
      this->Inner->writeValues(ownedEnd, count, this->Receive.data());
    }
    // Up: my last owned rows to `above`, `below`'s into my lower ghost rows.
    if (above >= 0)
    {
      this->Inner->readValues(ownedEnd - count, count, this->Send.data());
    }
    this->Comm.sendReceive(
      this->Send.data(), above >= 0 ? bytes : 0, above, this->Receive.data(), below >= 0 ? bytes : 0, below);
    if (below >= 0)
    {
      this->Inner->writeValues(ownedFirst - count, count, this->Receive.data());
    }
  }

  std::unique_ptr<HjbSolver> Inner;
  const Communicator& Comm;
  HjbGrid Whole;
  SharedHjbExpressions Compiled;
  Index First, Begin, End, Ghost; ///< rows of the last axis: local [First, ...), owned [Begin, End)
  Index RowNodes = 1;
  std::vector<double> Send, Receive;
};
} // namespace

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
  if (spec.Bounds[static_cast<size_t>(last)] == Boundary::Periodic)
  {
    return Status::invalidArgument(
      "a distributed HJB solve cuts the last axis into slabs, and it is periodic here: run on one rank");
  }
  const double reach = 1.25 * largestSpeed(spec, *compiled, grid) * dt / grid.Spacing[last];
  const Index ghost = static_cast<Index>(std::ceil(reach)) + HjbStencilRows;
  const Index rows = grid.Dims[last];
  const int size = comm.size(), rank = comm.rank();
  if (rows / size < ghost)
  {
    return Status::invalidArgument("the grid has " + std::to_string(rows) + " rows along its last axis for " +
      std::to_string(size) + " ranks, fewer than the " + std::to_string(ghost) +
      " each needs (the feet reach that far in one step): use fewer ranks or more nodes");
  }
  const Index begin = rows * rank / size, end = rows * (rank + 1) / size;
  const Index first = std::max<Index>(0, begin - ghost), stop = std::min(rows, end + ghost);
  HjbExpressionSpec local = spec; // the slab: the whole grid's coordinates, spacing and time steps, bitwise
  local.WindowFirst[static_cast<size_t>(last)] = first;
  local.WindowNodes[static_cast<size_t>(last)] = stop - first;
  if (!spec.InitialValues.empty())
  {
    const Index rowNodes = static_cast<Index>(spec.InitialValues.size()) / rows;
    local.InitialValues.assign(spec.InitialValues.begin() + static_cast<std::ptrdiff_t>(first * rowNodes),
      spec.InitialValues.begin() + static_cast<std::ptrdiff_t>(stop * rowNodes));
  }
  std::unique_ptr<HjbSolver> inner;
  SLTK_RETURN_IF_ERROR(comm.agree(makeExpressionSolver(local, inner)));
  solver =
    std::make_unique<DistributedSolver>(std::move(inner), comm, grid, std::move(compiled), first, begin, end, ghost);
  return Status::ok();
}

} // namespace sltk
