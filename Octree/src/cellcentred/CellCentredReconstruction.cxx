// SPDX-License-Identifier: GPL-2.0-or-later
#include "sltk/octree/CellCentredReconstruction.h"

#include "CellEnergy.h"
#include "CellTree.h"
#include "ClosestPointReinit.h"
#include "LeastSquaresQ1.h"
#include "PointValues.h"
#include "Propagation.h"

#include "sltk/exec/Logger.h"
#include "sltk/exec/Memory.h"
#include "sltk/levelset/CutOff.h"
#include "sltk/levelset/Ellipsoid.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/recon/StoppingRule.h"

#include <cmath>
#include <sstream>
#include <utility>

namespace sltk
{
namespace octree
{

namespace
{

/// The tree's cube (5.1): centred on the unit box, 2^m times its edge
/// (Delta_P = 2, 4.5), the smallest that holds the initial ellipsoid with
/// room for gamma and two cells around it; and the level of run 1, whose
/// cell is the first at most FirstCellSize.
struct TreeCube
{
  double Edge = 2.0;
  int FirstLevel = 0;
};

template <int D>
TreeCube treeCube(const Ellipsoid<D>& initial, double firstCell, double gammaFactor)
{
  double reach = 1.0;
  for (int a = 0; a < D; ++a)
  {
    reach = std::max(reach, std::fabs(initial.Centre[a]) + initial.SemiAxes[a]);
  }
  reach += (gammaFactor + 2.0) * firstCell;
  TreeCube cube;
  while (0.5 * cube.Edge < reach)
  {
    cube.Edge *= 2.0;
  }
  cube.FirstLevel = static_cast<int>(std::ceil(std::log2(cube.Edge / firstCell) - 1e-12));
  return cube;
}

/// The state of one iteration on the adapted tree T^{n+1}.
template <int D>
struct TreeState
{
  LeafGraph<D> Graph;
  std::vector<CellData<D>*> Data;
  std::vector<double> Phi;
  std::vector<CellPolynomial<D>> PhiPolynomials;
  std::vector<double> Distance;
  std::vector<CellPolynomial<D>> DistancePolynomials;
  std::vector<int> LeafOfPoint;
};

/// d at every leaf centre (5.2.3): the leaves holding points start from their
/// nearest point, then the propagation (5.8)-(5.9) over the whole tree
/// (every rank, collective), d at the ghosts too.
template <int D>
void distanceToCloud(const CellTree<D>& tree, const std::vector<std::array<double, D>>& points, TreeState<D>& s)
{
  Propagation<D> state;
  resetPropagation(s.Graph.size(), state);
  std::vector<int> front;
  for (size_t k = 0; k < points.size(); ++k)
  {
    const int leaf = s.LeafOfPoint[k];
    if (leaf < 0 || leaf >= s.Graph.Owned) // another rank's
    {
      continue;
    }
    const size_t i = static_cast<size_t>(leaf);
    const double q = pointDistance<D>(s.Graph.Centres[i], points[k]);
    if (std::isinf(state.Distance[i]))
    {
      front.push_back(static_cast<int>(i));
    }
    if (q < state.Distance[i])
    {
      state.Distance[i] = q;
      state.Reference[i] = points[k];
    }
  }
  propagate(s.Graph, front, state, std::numeric_limits<double>::infinity(), &tree); // and d at the ghosts
  s.Distance = std::move(state.Distance);
}

/// Builds the leaves, their polynomials of phi (5.5), d and its polynomials
/// (phi and d at the ghosts too). Collective.
template <int D>
void describeTree(
  const CellTree<D>& tree, const std::vector<std::array<double, D>>& points, const Context& ctx, TreeState<D>& s)
{
  tree.leaves(s.Graph, s.Data);
  s.Phi.assign(static_cast<size_t>(s.Graph.size()), 0.0);
  for (size_t i = 0; i < s.Data.size(); ++i)
  {
    s.Phi[i] = s.Data[i]->Phi;
  }
  tree.syncGhosts(s.Phi);
  fitLeastSquaresQ1(s.Graph, s.Phi, ctx, s.PhiPolynomials);
  tree.locate(points, s.LeafOfPoint);
  distanceToCloud<D>(tree, points, s);
  fitLeastSquaresQ1(s.Graph, s.Distance, ctx, s.DistancePolynomials);
}

struct StepModel
{
  double P = 1.0, Eta = 0.05, Energy = 1.0, TimeStep = 0.0, Beta = 0.0, Gamma = 0.0;
  double Singular = 0.0; ///< |grad phi| below which (4.26)'s mean of the neighbours replaces the step
};

/// The SL step (5.4) on this rank's leaves with |phi| < gamma (the cut-off
/// is zero beyond): gradients from the leaf's polynomials, the 2^(D-1) feet
/// of (4.22)/(4.24) interpolated by the polynomial of the leaf they fall in,
/// in one batch (PointValues.h: the other ranks' feet in one exchange).
/// Fails (numericalFailure) on every rank when a foot is not finite on one
/// (an infinite d, a zero energy). Collective.
template <int D>
Status semiLagrangianStep(const CellTree<D>& tree, const TreeState<D>& s, const StepModel& m, std::vector<double>& next)
{
  constexpr int Feet = 1 << (D - 1);
  next = s.Phi;
  std::vector<int> stepped;
  std::vector<std::array<double, D>> feet;
  Status failure;
  for (int i = 0; i < s.Graph.Owned && failure.isOk(); ++i)
  {
    const size_t k = static_cast<size_t>(i);
    const double phi = s.Phi[k];
    if (!(std::fabs(phi) < m.Gamma))
    {
      continue;
    }
    const auto g = s.PhiPolynomials[k].slope();
    double norm = 0.0;
    for (int a = 0; a < D; ++a)
    {
      norm += g[a] * g[a];
    }
    norm = std::sqrt(norm);
    if (norm < m.Singular)
    {
      // (4.26): the mean of the neighbours.
      double sum = 0.0;
      for (int j = s.Graph.Offsets[k]; j < s.Graph.Offsets[k + 1]; ++j)
      {
        sum += s.Phi[static_cast<size_t>(s.Graph.Neighbours[static_cast<size_t>(j)])];
      }
      next[k] = sum / (s.Graph.Offsets[k + 1] - s.Graph.Offsets[k]);
      continue;
    }
    const double d = s.Distance[k];
    const double scale = cutOff(phi, m.Beta, m.Gamma) * (m.P == 1.0 ? 1.0 : std::pow(d / m.Energy, m.P - 1.0));
    const auto gd = s.DistancePolynomials[k].slope();
    const double spread = std::sqrt(2.0 * scale * m.Eta * d * m.TimeStep / m.P);
    std::array<std::array<double, D>, D - 1> sigma;
    sltk::detail::tangentFrame(g, norm, sigma); // (4.23)/(4.25)
    const auto& x = s.Graph.Centres[k];
    for (int j = 0; j < Feet; ++j)
    {
      std::array<double, D> foot;
      for (int a = 0; a < D; ++a)
      {
        foot[a] = x[a] + scale * m.TimeStep * gd[a];
        for (int t = 0; t < D - 1; ++t)
        {
          foot[a] += spread * sigma[static_cast<size_t>(t)][a] * ((j >> t) & 1 ? 1.0 : -1.0); // xi_j in {+-1}^(D-1)
        }
        if (!std::isfinite(foot[a]))
        {
          failure = Status::numericalFailure("the cell-centred SL step met a foot that is not finite (d = " +
            std::to_string(d) + ", E_p = " + std::to_string(m.Energy) + "): check the cloud and the initial circle");
        }
      }
      feet.push_back(foot);
    }
    stepped.push_back(i);
  }
  SLTK_RETURN_IF_ERROR(tree.communicator().agree(failure));
  std::vector<double> values;
  SLTK_RETURN_IF_ERROR(valuesAtPoints<D>(tree, s.Graph, s.PhiPolynomials, feet, values));
  for (size_t f = 0; f < stepped.size(); ++f)
  {
    double sum = 0.0;
    for (size_t j = Feet * f; j < Feet * (f + 1); ++j)
    {
      sum += values[j];
    }
    next[static_cast<size_t>(stepped[f])] = sum / Feet;
  }
  return Status::ok();
}

/// Whether a rank holds more than `mostLeaves` leaves (collective).
template <int D>
bool tooManyLeaves(const CellTree<D>& tree, long mostLeaves)
{
  return tree.communicator().anyRank(tree.leafCount() > mostLeaves);
}

/// (5.6), first arrow: refine where |phi| < beta up to the run's level,
/// coarsen families flat at +-gamma (5.2.2: |grad phi| = 0), 2:1 balance,
/// and p4est's partition. False on every rank when the refinement outgrew
/// `mostLeaves` leaves on one. Collective.
template <int D>
bool adaptTree(CellTree<D>& tree, int level, int minimumLevel, double beta, double gamma, long mostLeaves)
{
  if (tree.refine(
        level, [beta](const CellData<D>& q, const std::array<double, D>&, double) { return std::fabs(q.Phi) < beta; },
        mostLeaves) < 0)
  {
    return false;
  }
  tree.coarsen(minimumLevel,
    [gamma](const CellData<D>* const family[CellTree<D>::Children])
    {
      for (int k = 0; k < CellTree<D>::Children; ++k)
      {
        const CellData<D>& q = *family[k];
        bool flat = std::fabs(q.Phi) >= gamma * (1.0 - 1e-12) && (q.Phi < 0.0) == (family[0]->Phi < 0.0);
        for (int a = 0; a < D; ++a)
        {
          flat = flat && q.Polynomial.C[static_cast<size_t>(1 << a)] == 0.0;
        }
        if (!flat)
        {
          return false;
        }
      }
      return true;
    });
  tree.balance();
  tree.partition();
  return !tooManyLeaves(tree, mostLeaves);
}

/// The refusal when the tree outgrows the memory (run 0: the uniform tree of MinimumLevel).
Status treeTooLarge(int run, int level, long mostLeaves)
{
  std::ostringstream m;
  m.precision(3);
  m << "the cell-centred tree of " << (run > 0 ? "run " + std::to_string(run) : std::string("MinimumLevel"))
    << " (level " << level << ") grew beyond " << mostLeaves
    << " leaves, what the memory budget (or available) holds at " << CellCentredBytesPerLeaf
    << " bytes a leaf: use fewer runs or a larger first cell (FirstCellSize)";
  return Status::outOfMemory(m.str());
}

/// phi and its polynomials into the leaves (what the next adaptation hands
/// on) and into s.
template <int D>
void storePhi(TreeState<D>& s, std::vector<double>&& phi, std::vector<CellPolynomial<D>>&& polynomials)
{
  for (size_t i = 0; i < s.Data.size(); ++i)
  {
    s.Data[i]->Phi = phi[i];
    s.Data[i]->Polynomial = polynomials[i];
  }
  s.Phi = std::move(phi);
  s.PhiPolynomials = std::move(polynomials);
}

/// The leaves of every rank at `level` (collective).
template <int D>
Index leavesAtLevel(const CellTree<D>& tree, const LeafGraph<D>& g, int level)
{
  std::int64_t count = 0;
  for (int i = 0; i < g.Owned; ++i)
  {
    count += g.Levels[static_cast<size_t>(i)] == level ? 1 : 0;
  }
  return static_cast<Index>(tree.communicator().allReduce(count, ReduceOp::Sum));
}

} // namespace

template <int D>
Status reconstructCellCentred(const ReconstructionPlan<D>& plan, const CellCentredOptions& options, const Context& ctx,
  CellCentredResult<D>& result, const Communicator& comm)
{
  const ReconstructionOptions& o = plan.Options;
  if (!(options.FirstCellSize > 0.0) || options.MinimumLevel < 0)
  {
    return Status::invalidArgument("reconstructCellCentred: need FirstCellSize > 0 and MinimumLevel >= 0");
  }
  if (!plan.InitialEllipsoid)
  {
    return Status::invalidArgument(
      "reconstructCellCentred: the thesis's octree starts from a circle or sphere around the cloud (5.3): use "
      "InitialGuess::BoundingSphere or BoundingEllipsoid");
  }
  const Ellipsoid<D>& initial = *plan.InitialEllipsoid;
  const TreeCube cube = treeCube(initial, options.FirstCellSize, o.GammaFactor);
  const int lastLevel = cube.FirstLevel + o.Runs - 1;
  const int DeepestLevel = CellTree<D>::deepestLevel();
  if (lastLevel > DeepestLevel || cube.FirstLevel < options.MinimumLevel)
  {
    std::ostringstream m;
    m << "reconstructCellCentred: levels " << cube.FirstLevel << ".." << lastLevel << " of the tree: need "
      << options.MinimumLevel << " <= level <= " << DeepestLevel;
    return Status::invalidArgument(m.str());
  }
  result = CellCentredResult<D>{};
  result.Box = plan.Box;
  result.DomainEdge = cube.Edge;
  result.DomainOrigin.fill(-0.5 * cube.Edge);
  const std::uint64_t memory = options.MemoryBudget ? options.MemoryBudget : availableMemoryBytes();
  // The neighbour lists' int offsets hold up to 2^31 entries, 56 a leaf at most (3D).
  const long mostLeaves = static_cast<long>(
    std::min<double>(memory > 0 ? static_cast<double>(memory) / CellCentredBytesPerLeaf : 1e300, 2147483647.0 / 56.0));
  // Each rank's budget is its own: the refusal of one is every rank's.
  SLTK_RETURN_IF_ERROR(
    comm.agree(std::ldexp(1.0, D * options.MinimumLevel) / comm.size() > static_cast<double>(mostLeaves)
        ? treeTooLarge(0, options.MinimumLevel, mostLeaves)
        : Status::ok()));
  std::unique_ptr<CellTree<D>> tree;
  SLTK_RETURN_IF_ERROR(CellTree<D>::create(comm, result.DomainOrigin, cube.Edge, options.MinimumLevel, tree));

  // Initial data (5.3): the signed distance to the circle or sphere, refined
  // around it as in (5.2) (|phi_0(x_i)| <= sqrt(D) Delta x_i) to run 1's level.
  const auto phi0 = [&initial](const std::array<double, D>& x) { return signedDistance(initial, x.data()); };
  if (tree->refine(
        cube.FirstLevel,
        [&phi0](const CellData<D>&, const std::array<double, D>& c, double h)
        { return std::fabs(phi0(c)) <= std::sqrt(double(D)) * h; },
        mostLeaves) < 0)
  {
    return treeTooLarge(1, cube.FirstLevel, mostLeaves);
  }
  tree->balance();
  tree->partition();
  if (tooManyLeaves(*tree, mostLeaves))
  {
    return treeTooLarge(1, cube.FirstLevel, mostLeaves);
  }
  TreeState<D> s;
  tree->leaves(s.Graph, s.Data);
  {
    const double gamma = o.GammaFactor * cube.Edge / std::ldexp(1.0, cube.FirstLevel);
    std::vector<double> phi(static_cast<size_t>(s.Graph.size())); // the ghosts' too: no exchange needed
    for (size_t i = 0; i < phi.size(); ++i)
    {
      phi[i] = cutLevel(phi0(s.Graph.Centres[i]), gamma);
    }
    std::vector<CellPolynomial<D>> polynomials;
    fitLeastSquaresQ1(s.Graph, phi, ctx, polynomials);
    storePhi(s, std::move(phi), std::move(polynomials));
  }

  const std::vector<std::array<double, D>>& points = plan.Cloud.Points;
  std::vector<double> energies;
  const double energyScale = std::pow(plan.Box.Scale, (2.0 + D - 1.0) / 2.0); // the user's units (recordsToUser)
  for (int run = 1; run <= o.Runs; ++run)
  {
    const int level = cube.FirstLevel + run - 1;
    const double dx = cube.Edge / std::ldexp(1.0, level); // (5.1)
    const RunParameters model = o.parameters(run);
    StepModel m;
    m.P = model.P;
    m.Eta = model.Eta;
    m.TimeStep = dx; // (5.12)
    m.Beta = o.BetaFactor * dx;
    m.Gamma = o.GammaFactor * dx;
    m.Singular = 1e-3 * m.TimeStep; // (4.26) with D = 1e-3, alpha = 1, as the uniform step
    for (CellData<D>* q : s.Data)   // the previous run's gamma was twice as wide
    {
      q->Phi = cutLevel(q->Phi, m.Gamma);
    }
    CellCentredRun record;
    record.Run = run;
    record.Level = level;
    record.CellSize = dx;
    energies.clear();
    long described = -1; // the tree's revision that s describes: phi was cut above
    int n = 0;
    for (; n < o.MaxIterations; ++n)
    {
      if (!adaptTree(*tree, level, options.MinimumLevel, m.Beta, m.Gamma, mostLeaves))
      {
        return treeTooLarge(run, level, mostLeaves);
      }
      if (tree->revision() != described) // else s holds this tree's leaves, d and phi^n already
      {
        describeTree<D>(*tree, points, ctx, s);
        described = tree->revision();
        ++record.TreeChanges;
      }
      // E_p of phi^n for the scale factor (4.32), E_2 for the stopping rule (4.33).
      const CellEnergy energy = cellEnergy(s.Graph, s.PhiPolynomials, s.DistancePolynomials, dx, m.P, 2.0, ctx, comm);
      if (energy.FrontLeaves == 0)
      {
        return Status::numericalFailure("run " + std::to_string(run) + ": the zero level set vanished");
      }
      m.Energy = std::pow(energy.Integral, 1.0 / m.P);
      energies.push_back(std::sqrt(energy.SecondIntegral));
      if (n >= o.MinIterations && energyStalled(energies, o.EnergyWindow, o.Tolerance))
      {
        break;
      }
      const bool interrupted = ctx.interrupter().wasInterrupted((run - 1 + double(n + 1) / o.MaxIterations) / o.Runs);
      SLTK_RETURN_IF_ERROR(comm.agree(interrupted ? Status::aborted() : Status::ok()));
      std::vector<double> phi;
      SLTK_RETURN_IF_ERROR(semiLagrangianStep(*tree, s, m, phi));
      tree->syncGhosts(phi);
      std::vector<CellPolynomial<D>> polynomials;
      fitLeastSquaresQ1(s.Graph, phi, ctx, polynomials);
      tree->syncGhosts(polynomials); // the ghosts' seeds
      reinitialiseByClosestPoints(s.Graph, polynomials, m.Gamma, ctx, phi, tree.get());
      tree->syncGhosts(phi);
      fitLeastSquaresQ1(s.Graph, phi, ctx, polynomials);
      storePhi(s, std::move(phi), std::move(polynomials));

      CellCentredIteration it;
      it.Run = run;
      it.Iteration = n + 1;
      it.Energy = energies.back() * energyScale;
      it.CloudError = cellCloudError<D>(points, s.LeafOfPoint, s.PhiPolynomials, s.Graph.Owned, comm) * plan.Box.Scale;
      it.Leaves = static_cast<Index>(tree->globalLeafCount());
      it.FinestLeaves = leavesAtLevel(*tree, s.Graph, level);
      it.UniformCells = Index(1) << (D * level);
      result.History.push_back(it);
      record.Energy = it.Energy;
      record.CloudError = it.CloudError;
      std::ostringstream line;
      line.precision(4);
      line << "cell-centred run " << run << " iteration " << n + 1 << ": E_2 " << it.Energy << ", Err_P "
           << it.CloudError << ", " << it.Leaves << " leaves";
      if (comm.rank() == 0)
      {
        ctx.logger().log(LogLevel::Debug, line.str());
      }
    }
    record.Iterations = n;
    result.Runs.push_back(record);
    std::ostringstream line;
    line.precision(4);
    line << "cell-centred run " << run << " (level " << level << "): " << n << " iterations (" << record.TreeChanges
         << " changed the tree), E_2 " << record.Energy << ", Err_P " << record.CloudError;
    if (comm.rank() == 0)
    {
      ctx.logger().log(LogLevel::Info, line.str());
    }
  }
  // s describes the final tree: no adaptation follows the last iteration's
  // described tree. Each rank returns its own leaves.
  result.Leaves.resize(s.Data.size());
  for (size_t i = 0; i < s.Data.size(); ++i)
  {
    CellCentredLeaf<D>& leaf = result.Leaves[i];
    leaf.Centre = s.Graph.Centres[i];
    leaf.Size = s.Graph.Sizes[i];
    leaf.Level = s.Graph.Levels[i];
    leaf.Phi = s.Phi[i];
    leaf.Distance = s.Distance[i];
    leaf.Polynomial = s.PhiPolynomials[i];
  }
  return Status::ok();
}

template Status reconstructCellCentred(
  const ReconstructionPlan<2>&, const CellCentredOptions&, const Context&, CellCentredResult<2>&, const Communicator&);
template Status reconstructCellCentred(
  const ReconstructionPlan<3>&, const CellCentredOptions&, const Context&, CellCentredResult<3>&, const Communicator&);

} // namespace octree
} // namespace sltk
