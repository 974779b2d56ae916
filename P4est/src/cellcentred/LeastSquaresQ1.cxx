// SPDX-License-Identifier: GPL-2.0-or-later
#include "LeastSquaresQ1.h"

#include <limits>

#include <Eigen/Dense>

namespace sltk
{
namespace p4est
{

template <int D>
CellPolynomial<D> fitLeastSquaresQ1(const LeafGraph<D>& graph, const std::vector<double>& values, int i)
{
  constexpr int Unknowns = CellPolynomial<D>::Terms - 1;
  using Vector = Eigen::Matrix<double, Unknowns, 1>;
  using Matrix = Eigen::Matrix<double, Unknowns, Unknowns>;
  const auto& x = graph.Centres[static_cast<size_t>(i)];
  const double h = graph.Sizes[static_cast<size_t>(i)];
  CellPolynomial<D> p;
  p.Centre = x;
  p.C[0] = values[static_cast<size_t>(i)];
  // Normal equations of the reduced system: sum over the neighbours j of
  // b_j b_j^T c = sum b_j (phi_j - phi_i), b_j the basis without 1 at x'_j.
  Matrix normal = Matrix::Zero();
  Vector right = Vector::Zero();
  for (int k = graph.Offsets[static_cast<size_t>(i)]; k < graph.Offsets[static_cast<size_t>(i) + 1]; ++k)
  {
    const size_t j = static_cast<size_t>(graph.Neighbours[static_cast<size_t>(k)]);
    double u[D];
    for (int a = 0; a < D; ++a)
    {
      u[a] = (graph.Centres[j][a] - x[a]) / h;
    }
    Vector b;
    for (int s = 1; s <= Unknowns; ++s)
    {
      double m = 1.0;
      for (int a = 0; a < D; ++a)
      {
        m *= (s >> a) & 1 ? u[a] : 1.0;
      }
      b[s - 1] = m;
    }
    normal.template selfadjointView<Eigen::Lower>().rankUpdate(b);
    right += b * (values[j] - p.C[0]);
  }
  // Cholesky (LDL^T) where the neighbours determine every coefficient (a
  // balanced tree's interior leaves), else the minimum-norm solution.
  const Eigen::LDLT<Matrix, Eigen::Lower> cholesky(normal);
  const auto pivots = cholesky.vectorD();
  const bool determined = cholesky.info() == Eigen::Success && pivots.minCoeff() > 1e-10 * pivots.maxCoeff();
  const Vector c = determined
    ? Vector(cholesky.solve(right))
    : Vector(
        normal.template selfadjointView<Eigen::Lower>().toDenseMatrix().completeOrthogonalDecomposition().solve(right));
  for (int s = 1; s <= Unknowns; ++s)
  {
    double scale = 1.0; // h^|S|: back from x' to x
    for (int a = 0; a < D; ++a)
    {
      scale *= (s >> a) & 1 ? h : 1.0;
    }
    p.C[static_cast<size_t>(s)] = c[s - 1] / scale;
  }
  return p;
}

template <int D>
void fitLeastSquaresQ1(const LeafGraph<D>& graph, const std::vector<double>& values, const Context& ctx,
  std::vector<CellPolynomial<D>>& polynomials)
{
  // A ghost's is its owner's (CellTree::syncGhosts): NaN until then, so that
  // a read before the exchange cannot pass for a value.
  CellPolynomial<D> unknown;
  unknown.C.fill(std::numeric_limits<double>::quiet_NaN());
  polynomials.resize(static_cast<size_t>(graph.Owned));
  polynomials.resize(static_cast<size_t>(graph.size()), unknown);
  ctx.parallelFor(0, graph.Owned,
    [&](Index b, Index e)
    {
      for (Index i = b; i < e; ++i)
      {
        polynomials[static_cast<size_t>(i)] = fitLeastSquaresQ1<D>(graph, values, static_cast<int>(i));
      }
    });
}

template CellPolynomial<2> fitLeastSquaresQ1(const LeafGraph<2>&, const std::vector<double>&, int);
template CellPolynomial<3> fitLeastSquaresQ1(const LeafGraph<3>&, const std::vector<double>&, int);
template void fitLeastSquaresQ1(
  const LeafGraph<2>&, const std::vector<double>&, const Context&, std::vector<CellPolynomial<2>>&);
template void fitLeastSquaresQ1(
  const LeafGraph<3>&, const std::vector<double>&, const Context&, std::vector<CellPolynomial<3>>&);

} // namespace p4est
} // namespace sltk
