// SPDX-License-Identifier: GPL-2.0-or-later
// CellTree<2> on p4est; CellTree3.cxx includes this file after
// p4est_to_p8est.h for CellTree<3> on p8est.
#include "CellTree.h"

#include "../P4estSupport.h"

#include "LeafTable.h"

#ifndef P4_TO_P8
#include <p4est.h>
#include <p4est_communication.h>
#include <p4est_extended.h>
#include <p4est_ghost.h>
#else
#include <p8est.h>
#include <p8est_communication.h>
#include <p8est_extended.h>
#include <p8est_ghost.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace sltk
{
namespace p4est
{

// The helpers' namespace is named by the dimension: this file is compiled
// twice (CellTree3.cxx), and Impl's members use its types.
#ifndef P4_TO_P8
namespace celltree2
#else
namespace celltree3
#endif
{
constexpr int Dim = P4EST_DIM;
constexpr int Children = P4EST_CHILDREN;
constexpr double RootLength = static_cast<double>(P4EST_ROOT_LEN);
using Point = std::array<double, Dim>;
using Data = CellData<Dim>;
using Tree = CellTree<Dim>;

/// A quadrant's integer coordinates.
std::array<p4est_qcoord_t, Dim> coordinates(const p4est_quadrant_t* q)
{
#ifndef P4_TO_P8
  return { q->x, q->y };
#else
  return { q->x, q->y, q->z };
#endif
}

/// What the p4est callbacks read and count (the forest's user_pointer).
struct Callbacks
{
  Point Origin{};
  double Edge = 1.0;
  int Level = 0; ///< the level refinement stops at, or coarsening stops above
  const typename Tree::RefineTest* Refine = nullptr;
  const typename Tree::CoarsenTest* Coarsen = nullptr;
  const LeafTable<Dim>* Leaves = nullptr; ///< the tree before a coarsening pass
  long Families = 0;

  Point centre(const p4est_quadrant_t* q) const
  {
    const double half = 0.5 * static_cast<double>(P4EST_QUADRANT_LEN(q->level));
    const auto at = coordinates(q);
    Point c;
    for (int a = 0; a < Dim; ++a)
    {
      c[a] = this->Origin[a] + this->Edge * (at[a] + half) / RootLength;
    }
    return c;
  }
  double size(const p4est_quadrant_t* q) const { return this->Edge * P4EST_QUADRANT_LEN(q->level) / RootLength; }
};

Callbacks& callbacksOf(p4est_t* p4est)
{
  return *static_cast<Callbacks*>(p4est->user_pointer);
}

Data& dataOf(const p4est_quadrant_t* q)
{
  return *static_cast<Data*>(q->p.user_data);
}

int refineWanted(p4est_t* p4est, p4est_topidx_t, p4est_quadrant_t* q)
{
  const Callbacks& c = callbacksOf(p4est);
  return q->level < c.Level && (*c.Refine)(dataOf(q), c.centre(q), c.size(q)) ? 1 : 0;
}

bool hasFinerNeighbour(const LeafTable<Dim>& table, const p4est_quadrant_t* q);

int coarsenWanted(p4est_t* p4est, p4est_topidx_t, p4est_quadrant_t* family[])
{
  const Callbacks& c = callbacksOf(p4est);
  if (family[0]->level <= c.Level)
  {
    return 0;
  }
  const Data* data[Children];
  for (int k = 0; k < Children; ++k)
  {
    data[k] = &dataOf(family[k]);
  }
  if (!(*c.Coarsen)(data))
  {
    return 0;
  }
  // A parent next to leaves two levels finer would break the 2:1 balance,
  // which would refine it again at once: such families stay.
  for (int k = 0; k < Children; ++k)
  {
    if (hasFinerNeighbour(*c.Leaves, family[k]))
    {
      return 0;
    }
  }
  return 1;
}

/// New leaves' data (5.2.2): children from the parent's polynomial, a parent
/// from its children's means.
void replaceLeaves(p4est_t* p4est, p4est_topidx_t, int outgoingCount, p4est_quadrant_t* outgoing[], int incomingCount,
  p4est_quadrant_t* incoming[])
{
  Callbacks& c = callbacksOf(p4est);
  ++c.Families;
  if (outgoingCount == 1)
  {
    const Data parent = dataOf(outgoing[0]);
    for (int k = 0; k < incomingCount; ++k)
    {
      Data& child = dataOf(incoming[k]);
      child.Polynomial = parent.Polynomial;
      child.Phi = parent.Polynomial.eval(c.centre(incoming[k]));
    }
    return;
  }
  Data mean;
  mean.Polynomial.Centre = c.centre(incoming[0]);
  for (int k = 0; k < outgoingCount; ++k)
  {
    const Data& child = dataOf(outgoing[k]);
    mean.Phi += child.Phi / outgoingCount;
    for (int s = 1; s < CellPolynomial<Dim>::Terms; ++s)
    {
      mean.Polynomial.C[static_cast<size_t>(s)] += child.Polynomial.C[static_cast<size_t>(s)] / outgoingCount;
    }
  }
  mean.Polynomial.C[0] = mean.Phi;
  dataOf(incoming[0]) = mean;
}

p4est_tree_t* onlyTree(p4est_t* p4est)
{
  return p4est_tree_array_index(p4est->trees, 0);
}

/// A quadrant's integer index at its level (LeafTable.h).
LeafTable<Dim>::Index indexAtLevel(const p4est_quadrant_t* q)
{
  const auto at = coordinates(q);
  LeafTable<Dim>::Index index;
  for (int a = 0; a < Dim; ++a)
  {
    index[a] = static_cast<std::uint32_t>(at[a] >> (P4EST_MAXLEVEL - q->level));
  }
  return index;
}

/// Calls visit(o, next) for every direction o of {-1, 0, 1}^D \ {0} whose
/// cell `next`, of the leaf's level next to it, lies in the tree.
template <class Visit>
void forEachNeighbourCell(int level, const LeafTable<Dim>::Index& at, Visit&& visit)
{
  const std::int64_t cells = std::int64_t(1) << level;
  int directions = 1;
  for (int a = 0; a < Dim; ++a)
  {
    directions *= 3;
  }
  for (int d = 0; d < directions; ++d)
  {
    std::array<int, Dim> o;
    LeafTable<Dim>::Index next;
    bool inside = true, centre = true;
    for (int a = 0, rest = d; a < Dim; ++a, rest /= 3)
    {
      o[a] = rest % 3 - 1;
      const std::int64_t n = static_cast<std::int64_t>(at[a]) + o[a];
      inside = inside && n >= 0 && n < cells;
      centre = centre && o[a] == 0;
      next[a] = static_cast<std::uint32_t>(n);
    }
    if (inside && !centre)
    {
      visit(o, next);
    }
  }
}

/// The neighbours of the leaf of `level` at `at` (face, edge and corner,
/// Fig. 5.3), appended to `out`: in each direction, the leaf of the same
/// level there, or the coarser leaf holding it, or (2:1 balance) the finer
/// leaves of that cell that touch this one.
void appendNeighbours(const LeafTable<Dim>& table, int level, const LeafTable<Dim>::Index& at, std::vector<int>& out)
{
  forEachNeighbourCell(level, at,
    [&](const std::array<int, Dim>& o, const LeafTable<Dim>::Index& next)
    {
      int leaf = table.find(level, next);
      if (leaf < 0 && level > 0)
      {
        LeafTable<Dim>::Index parent;
        for (int a = 0; a < Dim; ++a)
        {
          parent[a] = next[a] >> 1;
        }
        leaf = table.find(level - 1, parent);
      }
      if (leaf >= 0)
      {
        out.push_back(leaf);
        return;
      }
      int along = 0;
      for (int a = 0; a < Dim; ++a)
      {
        along += o[a] == 0 ? 1 : 0;
      }
      for (int k = 0; k < (1 << along); ++k) // the children of `next` on the side of this leaf
      {
        LeafTable<Dim>::Index child;
        int bit = 0;
        for (int a = 0; a < Dim; ++a)
        {
          const std::uint32_t t = o[a] < 0 ? 1u : o[a] > 0 ? 0u : static_cast<std::uint32_t>((k >> bit++) & 1);
          child[a] = 2 * next[a] + t;
        }
        leaf = table.find(level + 1, child);
        if (leaf >= 0)
        {
          out.push_back(leaf);
        }
      }
    });
}

/// Whether a leaf touches finer leaves (by a face, an edge or a corner): a
/// neighbouring cell of its size that is neither a leaf nor inside a coarser
/// leaf is divided. Before the balance a neighbour may be several levels
/// finer or coarser.
bool hasFinerNeighbour(const LeafTable<Dim>& table, const p4est_quadrant_t* q)
{
  const int level = q->level;
  bool finer = false;
  forEachNeighbourCell(level, indexAtLevel(q),
    [&](const std::array<int, Dim>&, const LeafTable<Dim>::Index& next)
    {
      bool whole = false; // a leaf of this level or a coarser one holds the cell
      for (int l = level; l >= 0 && !whole && !finer; --l)
      {
        LeafTable<Dim>::Index ancestor;
        for (int a = 0; a < Dim; ++a)
        {
          ancestor[a] = next[a] >> (level - l);
        }
        whole = table.find(l, ancestor) >= 0;
      }
      finer = finer || !whole;
    });
  return finer;
}

} // namespace celltree2 or celltree3

#ifndef P4_TO_P8
using namespace celltree2;
#else
using namespace celltree3;
#endif

template <>
struct CellTree<Dim>::Impl
{
  const Communicator* Comm = nullptr;
  p4est_connectivity_t* Connectivity = nullptr;
  p4est_t* Forest = nullptr;
  mutable p4est_ghost_t* Ghost = nullptr; ///< on several ranks: the ghost layer of the last refresh()
  mutable Callbacks Calls;
  mutable LeafTable<Dim> Table;
  mutable long TableRevision = -1;

  ~Impl()
  {
    if (this->Ghost)
    {
      p4est_ghost_destroy(this->Ghost);
    }
    if (this->Forest)
    {
      p4est_destroy(this->Forest);
    }
    if (this->Connectivity)
    {
      p4est_connectivity_destroy(this->Connectivity);
    }
  }

  bool distributed() const { return this->Comm->size() > 1; }

  /// The ghosts of the last refresh(): proc_offsets' count, not the array's,
  /// which p4est 2.2's expansion can leave longer (fixed upstream after 2.2).
  size_t ghostCount() const
  {
    return this->Ghost ? static_cast<size_t>(this->Ghost->proc_offsets[this->Forest->mpisize]) : 0;
  }

  /// The leaves of the current tree, and on several ranks a new ghost layer,
  /// in Table, when the tree changed (p4est's revision counter, the same on
  /// every rank: it moves on a global change). Collective on several ranks.
  void refresh() const
  {
    if (this->TableRevision == this->Forest->revision)
    {
      return;
    }
    const size_t owned = static_cast<size_t>(this->Forest->local_num_quadrants);
    size_t ghosts = 0;
    if (this->distributed())
    {
      if (this->Ghost)
      {
        p4est_ghost_destroy(this->Ghost);
      }
      this->Ghost = p4est_ghost_new(this->Forest, P4EST_CONNECT_FULL);
      p4est_ghost_expand(this->Forest, this->Ghost); // two layers: ClosestPointReinit.h's seeds
      ghosts = this->ghostCount();
    }
    this->Table.reset(owned + ghosts);
    for (size_t i = 0; i < owned + ghosts; ++i)
    {
      const p4est_quadrant_t* q = this->quadrant(i);
      this->Table.insert(q->level, indexAtLevel(q), static_cast<int>(i));
    }
    this->TableRevision = this->Forest->revision;
  }

  /// Leaf i of the last refresh(): this rank's below its leaf count, then the ghosts.
  const p4est_quadrant_t* quadrant(size_t i) const
  {
    const size_t owned = static_cast<size_t>(this->Forest->local_num_quadrants);
    return i < owned ? p4est_quadrant_array_index(&onlyTree(this->Forest)->quadrants, i)
                     : p4est_quadrant_array_index(&this->Ghost->ghosts, i - owned);
  }
};

template <>
CellTree<Dim>::CellTree(std::unique_ptr<Impl> impl)
  : P(std::move(impl))
{
}

template <>
CellTree<Dim>::~CellTree() = default;

template <>
Status CellTree<Dim>::create(
  const Communicator& comm, const Point& origin, double edge, int minimumLevel, std::unique_ptr<CellTree>& tree)
{
  if (!(edge > 0.0) || minimumLevel < 0 || minimumLevel > LeafTable<Dim>::DeepestLevel)
  {
    return Status::invalidArgument(
      "CellTree: need a positive edge and 0 <= minimumLevel <= " + std::to_string(LeafTable<Dim>::DeepestLevel));
  }
  MPI_Comm mpiComm = MPI_COMM_SELF;
  SLTK_RETURN_IF_ERROR(p4estCommunicator(comm, mpiComm));
  auto impl = std::make_unique<Impl>();
  impl->Comm = &comm;
  impl->Calls.Origin = origin;
  impl->Calls.Edge = edge;
#ifndef P4_TO_P8
  impl->Connectivity = p4est_connectivity_new_unitsquare();
#else
  impl->Connectivity = p8est_connectivity_new_unitcube();
#endif
  impl->Forest = p4est_new_ext(mpiComm, impl->Connectivity, 0, minimumLevel, 1, sizeof(Data), nullptr, &impl->Calls);
  p4est_tree_t* root = onlyTree(impl->Forest);
  for (size_t i = 0; i < root->quadrants.elem_count; ++i)
  {
    p4est_quadrant_t* q = p4est_quadrant_array_index(&root->quadrants, i);
    dataOf(q) = Data{};
    dataOf(q).Polynomial.Centre = impl->Calls.centre(q);
  }
  tree.reset(new CellTree(std::move(impl)));
  return Status::ok();
}

template <>
long CellTree<Dim>::leafCount() const
{
  return static_cast<long>(this->P->Forest->local_num_quadrants);
}

template <>
void CellTree<Dim>::partition()
{
  if (this->P->distributed())
  {
    p4est_partition_ext(this->P->Forest, 1, nullptr); // 1: a family stays on one rank
  }
}

template <>
long CellTree<Dim>::refine(int maximumLevel, const RefineTest& wants, long mostLeaves)
{
  Callbacks& c = this->P->Calls;
  c.Level = std::min(maximumLevel, LeafTable<Dim>::DeepestLevel);
  c.Refine = &wants;
  for (long total = 0;;) // one level at a time, so that the children's values are set before they are tested
  {
    c.Families = 0;
    p4est_refine_ext(this->P->Forest, 0, -1, refineWanted, nullptr, replaceLeaves);
    total += c.Families;
    if (this->P->Comm->anyRank(mostLeaves >= 0 && this->leafCount() > mostLeaves))
    {
      return -1;
    }
    if (!this->P->Comm->anyRank(c.Families > 0))
    {
      return total;
    }
    this->partition(); // the next level's leaves shared out again: the budget is each rank's
  }
}

template <>
long CellTree<Dim>::coarsen(int minimumLevel, const CoarsenTest& wants)
{
  Callbacks& c = this->P->Calls;
  c.Level = minimumLevel;
  c.Coarsen = &wants;
  c.Leaves = &this->P->Table;
  for (long total = 0;;)
  {
    c.Families = 0;
    this->P->refresh(); // the tree as this pass starts, with the ghosts' levels
    p4est_coarsen_ext(this->P->Forest, 0, 0, coarsenWanted, nullptr, replaceLeaves);
    total += c.Families;
    if (!this->P->Comm->anyRank(c.Families > 0))
    {
      return total;
    }
    // The new parents' families may straddle two ranks: bring each onto one,
    // so that the next pass merges what one rank would.
    this->partition();
  }
}

template <>
void CellTree<Dim>::balance()
{
  p4est_balance_ext(this->P->Forest, P4EST_CONNECT_FULL, nullptr, replaceLeaves);
}

template <>
std::int64_t CellTree<Dim>::globalLeafCount() const
{
  return static_cast<std::int64_t>(this->P->Forest->global_num_quadrants);
}

template <>
void CellTree<Dim>::leaves(LeafGraph<Dim>& graph, std::vector<Data*>& data) const
{
  const Callbacks& c = this->P->Calls;
  this->P->refresh();
  const p4est_t* forest = this->P->Forest;
  const size_t owned = static_cast<size_t>(forest->local_num_quadrants);
  const p4est_ghost_t* ghost = this->P->Ghost;
  const size_t n = owned + this->P->ghostCount();
  graph.Owned = static_cast<int>(owned);
  graph.Centres.resize(n);
  graph.Sizes.resize(n);
  graph.Levels.resize(n);
  graph.GlobalIds.resize(n);
  data.resize(owned);
  const auto describe = [&](size_t i, const p4est_quadrant_t* q, std::int64_t globalId)
  {
    graph.Centres[i] = c.centre(q);
    graph.Sizes[i] = c.size(q);
    graph.Levels[i] = q->level;
    graph.GlobalIds[i] = globalId;
  };
  const std::int64_t first = static_cast<std::int64_t>(forest->global_first_quadrant[forest->mpirank]);
  for (size_t i = 0; i < owned; ++i)
  {
    const p4est_quadrant_t* q = this->P->quadrant(i);
    describe(i, q, first + static_cast<std::int64_t>(i));
    data[i] = &dataOf(q);
  }
  for (int rank = 0; ghost && rank < forest->mpisize; ++rank) // ghosts by owner, owner's index
  {
    for (p4est_locidx_t g = ghost->proc_offsets[rank]; g < ghost->proc_offsets[rank + 1]; ++g)
    {
      const size_t i = owned + static_cast<size_t>(g);
      const p4est_quadrant_t* q = this->P->quadrant(i);
      describe(i, q, static_cast<std::int64_t>(forest->global_first_quadrant[rank]) + q->p.piggy3.local_num);
    }
  }
  graph.Offsets.assign(1, 0);
  graph.Neighbours.clear();
  const auto inGlobalOrder = [&graph](int a, int b)
  { return graph.GlobalIds[static_cast<size_t>(a)] < graph.GlobalIds[static_cast<size_t>(b)]; };
  for (size_t i = 0; i < n; ++i)
  {
    const p4est_quadrant_t* q = this->P->quadrant(i);
    const auto begin = static_cast<std::ptrdiff_t>(graph.Neighbours.size());
    appendNeighbours(this->P->Table, q->level, indexAtLevel(q), graph.Neighbours);
    std::sort(graph.Neighbours.begin() + begin, graph.Neighbours.end(), inGlobalOrder);
    graph.Neighbours.erase(
      std::unique(graph.Neighbours.begin() + begin, graph.Neighbours.end()), graph.Neighbours.end());
    graph.Offsets.push_back(static_cast<int>(graph.Neighbours.size()));
  }
}

template <>
void CellTree<Dim>::locate(const std::vector<Point>& points, std::vector<int>& leaf) const
{
  const Callbacks& c = this->P->Calls;
  if (!this->P->distributed())
  {
    this->P->refresh(); // on several ranks leaves() did, collectively
  }
  leaf.resize(points.size());
  for (size_t k = 0; k < points.size(); ++k)
  {
    Point t;
    for (int a = 0; a < Dim; ++a)
    {
      t[a] = (points[k][a] - c.Origin[a]) / c.Edge;
    }
    leaf[k] = this->P->Table.locate(t);
  }
}

template <>
void CellTree<Dim>::owners(const std::vector<Point>& points, std::vector<int>& rank) const
{
  const Callbacks& c = this->P->Calls;
  p4est_t* forest = this->P->Forest;
  rank.resize(points.size());
  const double cells = static_cast<double>(std::int64_t(1) << P4EST_QMAXLEVEL);
  for (size_t k = 0; k < points.size(); ++k)
  {
    // The point's cell at p4est's deepest level, clamped as LeafTable::locate clamps.
    p4est_quadrant_t q;
    std::memset(&q, 0, sizeof(q));
    q.level = P4EST_QMAXLEVEL;
    p4est_qcoord_t at[Dim];
    for (int a = 0; a < Dim; ++a)
    {
      const double t = (points[k][a] - c.Origin[a]) / c.Edge * cells;
      const double cell = t <= 0.0 ? 0.0 : t >= cells ? cells - 1.0 : std::floor(t);
      at[a] = static_cast<p4est_qcoord_t>(cell) << (P4EST_MAXLEVEL - P4EST_QMAXLEVEL);
    }
    q.x = at[0];
    q.y = at[1];
#ifdef P4_TO_P8
    q.z = at[2];
#endif
    rank[k] = p4est_comm_find_owner(forest, 0, &q, forest->mpirank);
  }
}

template <>
void CellTree<Dim>::syncGhostBytes(void* perLeaf, std::size_t bytes) const
{
  p4est_ghost_t* ghost = this->P->Ghost;
  if (!ghost)
  {
    return;
  }
  auto* base = static_cast<unsigned char*>(perLeaf);
  std::vector<void*> mirrors(ghost->mirrors.elem_count);
  for (size_t m = 0; m < mirrors.size(); ++m)
  {
    const p4est_quadrant_t* q = p4est_quadrant_array_index(&ghost->mirrors, m);
    mirrors[m] = base + static_cast<size_t>(q->p.piggy3.local_num) * bytes;
  }
  p4est_ghost_exchange_custom(this->P->Forest, this->P->Ghost, bytes, mirrors.data(),
    base + static_cast<size_t>(this->P->Forest->local_num_quadrants) * bytes);
}

template <>
const Communicator& CellTree<Dim>::communicator() const
{
  return *this->P->Comm;
}

template <>
int CellTree<Dim>::deepestLevel()
{
  return LeafTable<Dim>::DeepestLevel;
}

template <>
long CellTree<Dim>::revision() const
{
  return this->P->Forest->revision;
}

template <>
const CellTree<Dim>::Point& CellTree<Dim>::origin() const
{
  return this->P->Calls.Origin;
}

template <>
double CellTree<Dim>::edge() const
{
  return this->P->Calls.Edge;
}

} // namespace p4est
} // namespace sltk
