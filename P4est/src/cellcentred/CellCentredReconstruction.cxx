// SPDX-License-Identifier: GPL-2.0-or-later
#include "sltk/p4est/CellCentredReconstruction.h"

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
#include "sltk/recon/Reconstruction.h"
#include "sltk/recon/RunIterations.h"

#include <cmath>
#include <sstream>
#include <utility>

namespace sltk
{
namespace p4est
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

/// The band storage of a run on the cell-centred tree (sltk/recon/RunIterations.h):
/// the tree adapted to the band before every iteration (5.6), the energy on
/// the leaves' polynomials (CellEnergy.h), the SL step (5.4) and Saye's
/// reinitialisation with the propagation (5.2.4), each followed by the fits
/// (5.5). Records are in unit-box units; the leaves at the run's level per
/// iteration go to FinestLeaves.
template <int D>
class CellBand
{
public:
  CellBand(CellTree<D>& tree, TreeState<D>& state, const std::vector<std::array<double, D>>& points,
    const CellCentredOptions& options, const GridSpec<D>& grid, const BandWidths& widths, int level, long mostLeaves,
    int run, const Context& ctx)
    : Tree(tree)
    , S(state)
    , Points(points)
    , Options(options)
    , Grid(grid)
    , Widths(widths)
    , Level(level)
    , MostLeaves(mostLeaves)
    , Run(run)
    , Ctx(ctx)
  {
  }

  /// The run's level as a uniform grid over the tree's cube (its cell is Delta x_min, (5.1)).
  const GridSpec<D>& grid() const { return this->Grid; }

  /// (5.6): the tree adapted to phi^n's band; its leaves, fits and d described again when it changed.
  Status prepare()
  {
    if (!adaptTree(
          this->Tree, this->Level, this->Options.MinimumLevel, this->Widths.Beta, this->Widths.Gamma, this->MostLeaves))
    {
      return treeTooLarge(this->Run, this->Level, this->MostLeaves);
    }
    if (this->Tree.revision() != this->Described) // else S holds this tree's leaves, d and phi^n already
    {
      describeTree<D>(this->Tree, this->Points, this->Ctx, this->S);
      this->Described = this->Tree.revision();
      ++this->TreeChanges;
    }
    return Status::ok();
  }

  Status energy(const EnergyOptions& options, EnergyResult& ep)
  {
    const CellEnergy e = cellEnergy(this->S.Graph, this->S.PhiPolynomials, this->S.DistancePolynomials,
      this->Grid.Spacing[0], options.P, 2.0, this->Ctx, this->Tree.communicator());
    ep = EnergyResult{};
    ep.Integral = e.Integral;
    ep.SecondIntegral = e.SecondIntegral;
    ep.FrontCells = e.FrontLeaves;
    ep.Energy = std::pow(e.Integral, 1.0 / options.P);
    ep.SecondEnergy = std::sqrt(e.SecondIntegral);
    return Status::ok();
  }

  double farFraction(double far) const { return this->errors(far).FarFraction; }

  Status step(const LevelSetStepParameters& step)
  {
    StepModel m;
    m.P = step.P;
    m.Eta = step.Eta;
    m.Energy = step.Energy;
    m.TimeStep = step.TimeStep; // (5.12)
    m.Beta = step.Widths.Beta;
    m.Gamma = step.Widths.Gamma;
    m.Singular = 1e-3 * m.TimeStep; // (4.26) with D = 1e-3, alpha = 1, as the uniform step
    SLTK_RETURN_IF_ERROR(semiLagrangianStep(this->Tree, this->S, m, this->Next));
    this->Tree.syncGhosts(this->Next);
    return Status::ok();
  }

  Status reinitialise()
  {
    std::vector<CellPolynomial<D>> polynomials;
    fitLeastSquaresQ1(this->S.Graph, this->Next, this->Ctx, polynomials);
    this->Tree.syncGhosts(polynomials); // the ghosts' seeds
    reinitialiseByClosestPoints(this->S.Graph, polynomials, this->Widths.Gamma, this->Ctx, this->Next, &this->Tree);
    this->Tree.syncGhosts(this->Next);
    fitLeastSquaresQ1(this->S.Graph, this->Next, this->Ctx, polynomials);
    storePhi(this->S, std::move(this->Next), std::move(polynomials));
    return Status::ok();
  }

  bool measure(IterationRecord& it, bool interrupted)
  {
    it.CloudError = this->errors(0.0).Mean;
    it.Leaves = static_cast<Index>(this->Tree.globalLeafCount());
    it.UniformNodes = Index(1) << (D * this->Level);
    this->FinestLeaves.push_back(leavesAtLevel(this->Tree, this->S.Graph, this->Level));
    return !this->Tree.communicator().agree(interrupted ? Status::aborted() : Status::ok()).isOk();
  }

  /// The thesis's cell-centred scheme is kept as the thesis runs it (a
  /// comparison): its leaves' values are not merged (IsolatedNodes.h).
  Index mergeIsolatedNodes() { return 0; }

  void finish(RunRecord<D>& record, double far) const
  {
    const CellCloudErrors e = this->errors(far);
    record.FarPoints = e.FarFraction;
    if (record.Iterations == 0)
    {
      record.CloudError = e.Mean;
    }
  }

  std::string describe() const
  {
    return "; level " + std::to_string(this->Level) + ", " + std::to_string(this->Tree.globalLeafCount()) +
      " leaves, " + std::to_string(this->TreeChanges) + " iterations changed the tree";
  }

  int treeChanges() const { return this->TreeChanges; }
  const std::vector<Index>& finestLeaves() const { return this->FinestLeaves; }

private:
  CellCloudErrors errors(double far) const
  {
    return cellCloudErrors<D>(
      this->Points, this->S.LeafOfPoint, this->S.PhiPolynomials, this->S.Graph.Owned, far, this->Tree.communicator());
  }

  CellTree<D>& Tree;
  TreeState<D>& S;
  const std::vector<std::array<double, D>>& Points;
  const CellCentredOptions& Options;
  const GridSpec<D> Grid;
  const BandWidths Widths; // beta and gamma (1.56) of the run's Delta x_min
  const int Level;
  const long MostLeaves;
  const int Run;
  const Context& Ctx;
  long Described = -1; // the tree's revision that S describes: phi was cut before the run
  int TreeChanges = 0;
  std::vector<double> Next; // phi^{n+1} between the step and the reinitialisation
  std::vector<Index> FinestLeaves;
};
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
  const double energyScale = std::pow(plan.Box.Scale, (2.0 + D - 1.0) / 2.0); // the user's units (recordsToUser)
  for (int run = 1; run <= o.Runs; ++run)
  {
    const int level = cube.FirstLevel + run - 1;
    GridSpec<D> grid; // the run's level over the tree's cube: its cell is Delta x_min (5.1)
    for (int a = 0; a < D; ++a)
    {
      grid.Dims[a] = (Index(1) << level) + 1;
      grid.Spacing[a] = cube.Edge / std::ldexp(1.0, level);
      grid.Origin[a] = result.DomainOrigin[static_cast<size_t>(a)];
    }
    const BandWidths widths = BandWidths::forSpacing(grid.Spacing[0], o.BetaFactor, o.GammaFactor);
    for (CellData<D>* q : s.Data) // the previous run's gamma was twice as wide
    {
      q->Phi = cutLevel(q->Phi, widths.Gamma);
    }
    // Algorithm 1's iterations, as the uniform grids and the tiled band run them.
    CellBand<D> band(*tree, s, points, options, grid, widths, level, mostLeaves, run, ctx);
    ReconstructionResult<D> records;
    bool vanished = false;
    const Status status = iterateRun<D>(band, o, run, plan.CloudSpacing, ctx, records, vanished);
    for (size_t k = 0; k < records.History.size(); ++k)
    {
      const IterationRecord& r = records.History[k];
      CellCentredIteration it;
      it.Run = run;
      it.Iteration = r.Iteration;
      it.Energy = r.Energy * energyScale;
      it.CloudError = r.CloudError * plan.Box.Scale;
      it.Leaves = r.Leaves;
      it.FinestLeaves = band.finestLeaves()[k];
      it.UniformCells = r.UniformNodes;
      result.History.push_back(it);
    }
    SLTK_RETURN_IF_ERROR(status);
    const RunRecord<D>& done = records.Runs.back();
    CellCentredRun record;
    record.Run = run;
    record.Level = level;
    record.CellSize = grid.Spacing[0];
    record.Iterations = done.Iterations;
    record.TreeChanges = band.treeChanges();
    record.Energy = done.Iterations ? result.History.back().Energy : done.Energy * energyScale;
    record.CloudError = done.Iterations ? result.History.back().CloudError : done.CloudError * plan.Box.Scale;
    result.Runs.push_back(record);
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

} // namespace p4est
} // namespace sltk
