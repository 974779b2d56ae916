// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file CellTree.h
/// The tree of the cell-centred scheme (thesis 5.1): one p4est tree (a
/// quadtree in 2D, p8est's octree in 3D) over a square or cube, on one
/// process, each leaf carrying phi and its polynomial (CellPolynomial.h) as
/// p4est user data, so that p4est's refinement, coarsening and 2:1 balance
/// hand new leaves their values (5.2.2):
///  - a child takes the value of its parent's polynomial at its centre, and
///    inherits the polynomial;
///  - a coarsened family gives its parent the mean of its values and of its
///    polynomials' coefficients.
/// Neighbours and points are found through a hash table of the leaves by
/// level and position (LeafTable.h), rebuilt when p4est changes the tree:
/// on one process it finds the leaf p4est_search_local would (5.2.1,
/// "Localizing the feet"), without that search's cost, which grows with the
/// points times the depth times 2^D (62% of the time on Cube&Spheres).

#include "sltk/core/Status.h"
#include "sltk/octree/CellPolynomial.h"

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace sltk
{
namespace octree
{

/// A leaf's user data.
template <int D>
struct CellData
{
  double Phi = 0.0;
  CellPolynomial<D> Polynomial;
};

/// The leaves of the tree in Morton order, with their face, edge and corner
/// neighbours (Fig. 5.3; at most 12 in 2D and 56 in 3D under 2:1 balance).
template <int D>
struct LeafGraph
{
  std::vector<std::array<double, D>> Centres;
  std::vector<double> Sizes;
  std::vector<int> Levels;
  std::vector<int> Offsets; ///< neighbours of leaf i: Neighbours[Offsets[i] .. Offsets[i + 1])
  std::vector<int> Neighbours;

  int size() const { return static_cast<int>(this->Centres.size()); }
};

template <int D>
class CellTree
{
public:
  using Point = std::array<double, D>;
  static constexpr int Children = 1 << D;

  /// A tree over [origin, origin + edge]^D refined uniformly to `minimumLevel`.
  static Status create(const Point& origin, double edge, int minimumLevel, std::unique_ptr<CellTree>& tree);
  ~CellTree();

  using RefineTest = std::function<bool(const CellData<D>& data, const Point& centre, double size)>;
  using CoarsenTest = std::function<bool(const CellData<D>* const family[Children])>;

  /// Refines the leaves below `maximumLevel` that `wants`, then their
  /// children that it wants, until none is left (recursive, 5.1.3), one
  /// level at a time. Returns the families created, or -1 when a level left
  /// more than `mostLeaves` leaves (refinement stopped there).
  long refine(int maximumLevel, const RefineTest& wants, long mostLeaves = -1);
  /// The number of leaves.
  long leafCount() const;
  /// Coarsens the families above `minimumLevel` that `wants`, recursively.
  long coarsen(int minimumLevel, const CoarsenTest& wants);
  /// 2:1 balance across faces, edges and corners.
  void balance();

  /// The leaves in Morton order: their graph and their data (valid until
  /// the tree changes).
  void leaves(LeafGraph<D>& graph, std::vector<CellData<D>*>& data) const;
  /// The leaf holding each point (Morton index); points outside the tree's
  /// cube are taken to the nearest leaf.
  void locate(const std::vector<Point>& points, std::vector<int>& leaf) const;
  /// p4est's revision counter: unchanged while the leaves are.
  long revision() const;
  /// The deepest level a tree may reach.
  static int deepestLevel();

  const Point& origin() const;
  double edge() const;

private:
  struct Impl;
  explicit CellTree(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> P;
};

} // namespace octree
} // namespace sltk
