// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file CellTree.h
/// The tree of the cell-centred scheme (thesis 5.1): one p4est tree (a
/// quadtree in 2D, p8est's octree in 3D) over a square or cube, shared out
/// over the ranks of a communicator in p4est's Morton partition, each leaf
/// carrying phi and its polynomial (CellPolynomial.h) as p4est user data, so
/// that p4est's refinement, coarsening, 2:1 balance and partition hand new
/// or moved leaves their values (5.2.2):
///  - a child takes the value of its parent's polynomial at its centre, and
///    inherits the polynomial;
///  - a coarsened family gives its parent the mean of its values and of its
///    polynomials' coefficients.
/// Neighbours and points are found through a hash table of the leaves by
/// level and position (LeafTable.h), rebuilt when p4est changes the tree:
/// it finds the leaf p4est_search_local would (5.2.1, "Localizing the
/// feet"), without that search's cost, which grows with the points times the
/// depth times 2^D (62% of the time on Cube&Spheres). On several ranks the
/// table holds the rank's leaves and its ghosts (p4est's ghost layer,
/// expanded once: the other ranks' leaves that touch its own, by a face, an
/// edge or a corner, and the leaves that touch those, which the
/// reinitialisation's seeds need, ClosestPointReinit.h);
/// a point beyond them belongs to the rank owners() names, p4est's
/// p4est_comm_find_owner on the partition's Morton positions (what
/// p4est_search_partition finds for one point).

#include "sltk/core/Status.h"
#include "sltk/exec/Communicator.h"
#include "sltk/p4est/CellPolynomial.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <type_traits>
#include <vector>

namespace sltk
{
namespace p4est
{

/// A leaf's user data.
template <int D>
struct CellData
{
  double Phi = 0.0;
  CellPolynomial<D> Polynomial;
};

/// The leaves of this rank in Morton order, then its ghosts (in p4est's
/// order), with their face, edge and corner neighbours (Fig. 5.3; at most 12
/// in 2D and 56 in 3D under 2:1 balance), listed in the global Morton order,
/// so that every sum over them is added in the order of one rank. The lists
/// of the ghosts of the first layer are whole; those of the second layer
/// hold only the neighbours the rank has.
template <int D>
struct LeafGraph
{
  std::vector<std::array<double, D>> Centres;
  std::vector<double> Sizes;
  std::vector<int> Levels;
  std::vector<int> Offsets; ///< neighbours of leaf i: Neighbours[Offsets[i] .. Offsets[i + 1])
  std::vector<int> Neighbours;
  std::vector<std::int64_t> GlobalIds; ///< a leaf's place in the global Morton order
  int Owned = 0;                       ///< leaves [0, Owned) are this rank's; [Owned, size()) its ghosts

  int size() const { return static_cast<int>(this->Centres.size()); }
};

template <int D>
class CellTree
{
public:
  using Point = std::array<double, D>;
  static constexpr int Children = 1 << D;

  /// A tree over [origin, origin + edge]^D refined uniformly to `minimumLevel`,
  /// shared out over `comm`'s ranks (which must outlive the tree). Collective.
  static Status create(
    const Communicator& comm, const Point& origin, double edge, int minimumLevel, std::unique_ptr<CellTree>& tree);
  ~CellTree();

  using RefineTest = std::function<bool(const CellData<D>& data, const Point& centre, double size)>;
  using CoarsenTest = std::function<bool(const CellData<D>* const family[Children])>;

  /// Refines the leaves below `maximumLevel` that `wants`, then their
  /// children that it wants, until none is left on any rank (recursive,
  /// 5.1.3), one level at a time. Returns the families created on this
  /// rank, or -1 on every rank when a level left more than `mostLeaves`
  /// leaves on one (refinement stopped there). Collective.
  long refine(int maximumLevel, const RefineTest& wants, long mostLeaves = -1);
  /// The number of leaves of this rank.
  long leafCount() const;
  /// The number of leaves of all ranks.
  std::int64_t globalLeafCount() const;
  /// Coarsens the families above `minimumLevel` that `wants`, one level a
  /// pass, until no rank coarsens any, with partition() before every pass
  /// but the first (the caller's), so that every family lies on one rank and
  /// the passes merge what they merge on one rank. Collective.
  long coarsen(int minimumLevel, const CoarsenTest& wants);
  /// 2:1 balance across faces, edges and corners. Collective.
  void balance();
  /// p4est's partition: equal numbers of leaves per rank in Morton order,
  /// with every family on one rank, so that coarsen() can merge it. Collective.
  void partition();

  /// This rank's leaves in Morton order, then its ghosts: their graph, and
  /// the data of its own leaves (valid until the tree changes). Collective.
  void leaves(LeafGraph<D>& graph, std::vector<CellData<D>*>& data) const;
  /// The leaf holding each point (an index of the last leaves() graph), or
  /// -1 when that leaf is neither this rank's nor a ghost; points outside
  /// the tree's cube are taken to the nearest leaf.
  void locate(const std::vector<Point>& points, std::vector<int>& leaf) const;
  /// The rank whose leaf holds each point (with locate()'s convention outside the cube).
  void owners(const std::vector<Point>& points, std::vector<int>& rank) const;
  /// Copies every ghost's entry of a per-leaf array (indexed as the last
  /// leaves() graph) from its owner's entry of the same array. Collective.
  template <class T>
  void syncGhosts(std::vector<T>& perLeaf) const
  {
    static_assert(std::is_trivially_copyable<T>::value, "the ghost exchange sends raw bytes");
    this->syncGhostBytes(perLeaf.data(), sizeof(T));
  }
  const Communicator& communicator() const;
  /// p4est's revision counter: unchanged while the tree is (p4est moves it
  /// on every rank when any rank's leaves change).
  long revision() const;
  /// The deepest level a tree may reach.
  static int deepestLevel();

  const Point& origin() const;
  double edge() const;

private:
  void syncGhostBytes(void* perLeaf, std::size_t bytes) const;
  struct Impl;
  explicit CellTree(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> P;
};

} // namespace p4est
} // namespace sltk
