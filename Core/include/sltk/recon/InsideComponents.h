// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file InsideComponents.h
/// How many pieces a result has (Documentation/Numerics.md, "Pieces against the cloud's
/// components"): the connected components of its inside region {phi < 0}, the grid's nodes
/// linked to their face neighbours, whatever the storage and the ranks.
///
/// Each rank labels the runs of inside nodes it owns along x (a union-find over the
/// runs: memory in the runs, not the nodes), links them to the runs of the lines below
/// them, and sends what links its runs to the other ranks' (the neighbour run's id,
/// read from its ghost copy, and its root): every rank then merges the same pairs, so
/// the count is the same on any number of ranks.
///
/// A storage's `Nodes` (every call on this rank; whole-grid node indices):
///  - `dims()`: the whole grid's nodes per axis;
///  - `lines(first, end)`: the lines (nodes of equal coordinates 1..D-1, coordinate 1
///    fastest) this rank owns nodes on;
///  - `owner(i)`: the rank that owns node i (any rank id for a node it does not own);
///  - `inside(i)`: phi(i) < 0, for the nodes this rank owns and their face neighbours;
///  - `period()`: runs break where x is a multiple of it (a tile's edge: the run of a
///    neighbour then lies in one tile, which the ghost copies hold).

#include "sltk/core/DisjointSets.h"
#include "sltk/exec/Communicator.h"
#include "sltk/grid/GridField.h"
#include "sltk/grid/Slabs.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace sltk
{

namespace detail
{
/// A run of inside nodes X0 .. X1 - 1 of one line; Id: the whole-grid index of its first node.
struct InsideRun
{
  Index Id = 0;
  std::int32_t X0 = 0, X1 = 0;
  bool Anchor = false; ///< another rank owns a neighbour after it (it may name this run)
};

template <int D>
std::array<Index, D> lineNode(Index line, const std::array<Index, D>& dims)
{
  std::array<Index, D> i{};
  for (int a = 1; a < D; ++a)
  {
    i[a] = line % dims[a];
    line /= dims[a];
  }
  return i;
}

template <int D>
Index wholeIndex(const std::array<Index, D>& i, const std::array<Index, D>& dims)
{
  Index k = 0;
  for (int a = D - 1; a >= 0; --a)
  {
    k = k * dims[a] + i[a];
  }
  return k;
}

/// The id of the run through node `i` as its owner labels it: back along x while inside,
/// of the same owner, and not at a break.
template <int D, class Nodes>
Index runIdThrough(const Nodes& nodes, std::array<Index, D> i)
{
  const int owner = nodes.owner(i);
  while (i[0] > 0 && i[0] % nodes.period() != 0)
  {
    std::array<Index, D> left = i;
    --left[0];
    if (!nodes.inside(left) || nodes.owner(left) != owner)
    {
      break;
    }
    i = left;
  }
  return wholeIndex<D>(i, nodes.dims());
}

/// The runs of one rank, their union-find and the pairs that link them to other ranks'.
template <int D, class Nodes>
class InsideRuns
{
public:
  InsideRuns(const Nodes& nodes, int rank)
    : N(nodes)
    , Rank(rank)
  {
  }

  /// Labels the lines [first, end).
  void label(Index first, Index end)
  {
    this->First = first;
    this->LineBegin.assign(static_cast<size_t>(end - first + 1), 0);
    const Index nx = this->N.dims()[0];
    for (Index line = first; line < end; ++line)
    {
      this->LineBegin[static_cast<size_t>(line - first)] = static_cast<Index>(this->Runs.size());
      this->Current = line;
      std::array<Index, D> i = lineNode<D>(line, this->N.dims());
      for (Index x = 0; x < nx;)
      {
        i[0] = x;
        if (!this->mine(i))
        {
          ++x;
          continue;
        }
        InsideRun run;
        run.X0 = static_cast<std::int32_t>(x);
        run.Id = wholeIndex<D>(i, this->N.dims());
        do
        {
          i[0] = ++x;
        } while (x < nx && x % this->N.period() != 0 && this->mine(i));
        run.X1 = static_cast<std::int32_t>(x);
        this->Runs.push_back(run);
        this->Parent.push_back(static_cast<Index>(this->Runs.size()) - 1);
        this->link(line, i);
      }
    }
    this->LineBegin.back() = static_cast<Index>(this->Runs.size());
  }

  /// This rank's roots (their ids) and the pairs (id, root id) other ranks' runs need.
  void results(std::vector<Index>& roots, std::vector<std::array<Index, 2>>& pairs)
  {
    for (Index k = 0; k < static_cast<Index>(this->Runs.size()); ++k)
    {
      const Index root = this->Runs[static_cast<size_t>(findRoot(this->Parent, k))].Id;
      if (root == this->Runs[static_cast<size_t>(k)].Id)
      {
        roots.push_back(root);
      }
      else if (this->Runs[static_cast<size_t>(k)].Anchor)
      {
        pairs.push_back({ this->Runs[static_cast<size_t>(k)].Id, root });
      }
    }
    for (const auto& remote : this->Remote)
    {
      pairs.push_back({ remote[0], this->Runs[static_cast<size_t>(findRoot(this->Parent, remote[1]))].Id });
    }
  }

private:
  bool mine(const std::array<Index, D>& i) const { return this->N.owner(i) == this->Rank && this->N.inside(i); }

  /// Links the last run (of `line`; `after` its line's node) to the runs before it along
  /// x and in the lines below along each other axis; marks it an anchor.
  void link(Index line, const std::array<Index, D>& after)
  {
    const Index k = static_cast<Index>(this->Runs.size()) - 1;
    InsideRun& run = this->Runs.back();
    std::array<Index, D> i = after;
    i[0] = run.X0 - 1;
    if (run.X0 > 0 && this->N.inside(i))
    {
      this->join(k, i, line);
    }
    i[0] = run.X1;
    run.Anchor = run.X1 < this->N.dims()[0] && this->N.owner(i) != this->Rank;
    Index stride = 1;
    for (int a = 1; a < D; ++a)
    {
      for (Index x = run.X0; x < run.X1; ++x)
      {
        i = after;
        i[0] = x;
        ++i[a];
        run.Anchor = run.Anchor || (i[a] < this->N.dims()[a] && this->N.owner(i) != this->Rank);
        i[a] -= 2;
        // A run below: one join for the nodes of one run (the next node continues it).
        if (i[a] >= 0 && this->N.inside(i) && (x == run.X0 || !this->sameRunAsLeft(i)))
        {
          this->join(k, i, line - stride);
        }
      }
      stride *= this->N.dims()[a];
    }
  }

  /// Whether node i continues the run of the node on its left (inside, same owner, no break).
  bool sameRunAsLeft(const std::array<Index, D>& i) const
  {
    std::array<Index, D> left = i;
    --left[0];
    return i[0] % this->N.period() != 0 && this->N.inside(left) && this->N.owner(left) == this->N.owner(i);
  }

  /// Joins run k with the run through inside node i of an earlier line `line` (this rank's
  /// runs; its last before k when `line` is k's): this rank's, or a pair to send.
  void join(Index k, const std::array<Index, D>& i, Index line)
  {
    if (this->N.owner(i) != this->Rank)
    {
      this->Remote.push_back({ runIdThrough<D>(this->N, i), k });
      return;
    }
    const size_t l = static_cast<size_t>(line - this->First);
    const auto first = this->Runs.begin() + this->LineBegin[l];
    const auto last = this->Runs.begin() + (line == this->Current ? k : this->LineBegin[l + 1]);
    const auto found =
      std::upper_bound(first, last, i[0], [](Index x, const InsideRun& r) { return x < static_cast<Index>(r.X1); });
    const Index other = static_cast<Index>(found - this->Runs.begin());
    unite(this->Parent, k, other);
  }

  const Nodes& N;
  const int Rank;
  Index First = 0, Current = 0; // the first line, the line being labelled
  std::vector<InsideRun> Runs;
  std::vector<Index> Parent;
  std::vector<Index> LineBegin;             // first run of each line
  std::vector<std::array<Index, 2>> Remote; // (another rank's run id, this rank's run)
};
} // namespace detail

/// The connected components of {phi < 0} of a storage's `nodes` over the ranks of `comm`
/// (collective): the same count on any number of ranks.
template <int D, class Nodes>
std::int64_t insideComponents(const Nodes& nodes, const Communicator& comm)
{
  Index first = 0, end = 0;
  nodes.lines(first, end);
  detail::InsideRuns<D, Nodes> runs(nodes, comm.rank());
  runs.label(first, end);
  std::vector<Index> roots;
  std::vector<std::array<Index, 2>> pairs;
  runs.results(roots, pairs);
  roots = comm.allGatherV(roots);
  pairs = comm.allGatherV(pairs);
  // One union-find over every id the ranks named (the merge of their boundary pairs).
  std::vector<Index> ids = roots;
  for (const auto& p : pairs)
  {
    ids.insert(ids.end(), { p[0], p[1] });
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const auto at = [&](Index id)
  { return static_cast<Index>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin()); };
  std::vector<Index> parent = singletonForest<Index>(ids.size());
  for (const auto& p : pairs)
  {
    unite(parent, at(p[0]), at(p[1]));
  }
  std::vector<Index> distinct;
  for (Index r : roots)
  {
    distinct.push_back(findRoot(parent, at(r)));
  }
  std::sort(distinct.begin(), distinct.end());
  return static_cast<std::int64_t>(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
}

/// The nodes of a uniform result on this rank's slab (grid/Slabs.h): `phi` is the window,
/// rows slab.First .. slab.Stop - 1 of `whole`; this rank owns rows slab.Begin .. End - 1.
template <int D>
class SlabNodes
{
public:
  SlabNodes(const GridField<D>& phi, const GridSpec<D>& whole, const SlabPlan& slab, int rank)
    : Phi(phi)
    , Dims(whole.Dims)
    , Slab(slab)
    , Rank(rank)
  {
  }
  const std::array<Index, D>& dims() const { return this->Dims; }
  void lines(Index& first, Index& end) const
  {
    const Index perRow = this->lineCount() / this->Dims[D - 1];
    first = this->Slab.Begin * perRow;
    end = this->Slab.End * perRow;
  }
  int owner(const std::array<Index, D>& i) const
  {
    const Index row = i[D - 1];
    return row < this->Slab.Begin ? this->Rank - 1 : row >= this->Slab.End ? this->Rank + 1 : this->Rank;
  }
  bool inside(std::array<Index, D> i) const
  {
    i[D - 1] -= this->Slab.First;
    return this->Phi(i) < 0.0;
  }
  Index period() const { return this->Dims[0]; }

private:
  Index lineCount() const
  {
    Index n = 1;
    for (int a = 1; a < D; ++a)
    {
      n *= this->Dims[a];
    }
    return n;
  }

  const GridField<D>& Phi;
  const std::array<Index, D> Dims;
  const SlabPlan Slab;
  const int Rank;
};

} // namespace sltk
