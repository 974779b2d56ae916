// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file GridField.h
/// Nodal values on a GridSpec, stored with G ghost layers per side so that
/// interpolation stencils read memory without branches. Layout: x fastest
/// (the VTK point order). fillGhosts() applies the per-axis boundary policy:
/// linear extrapolation or periodic wrap (thesis 3.5, Documentation/Numerics.md:
/// two ghost layers by linear extrapolation).

#include "sltk/grid/GridSpec.h"
#include "sltk/grid/NodeIndexer.h"

#include <vector>

namespace sltk
{

template <int D, class T = double>
class GridField
{
public:
  using Scalar = T;
  static constexpr int Dim = D;

  GridField() = default;
  GridField(const GridSpec<D>& spec, int ghost, T value = T(0)) { this->resize(spec, ghost, value); }

  void resize(const GridSpec<D>& spec, int ghost, T value = T(0))
  {
    this->Values.assign(static_cast<size_t>(this->setShape(spec, ghost)), value);
  }

  /// The same shape as resize() gives, the values left as they were (the new
  /// ones zero): for a scratch copy that writes every value it reads.
  void reshape(const GridSpec<D>& spec, int ghost)
  {
    const auto total = static_cast<size_t>(this->setShape(spec, ghost));
    this->Values.reserve(total); // exactly: resize alone may double the capacity
    this->Values.resize(total);
  }

  const GridSpec<D>& spec() const { return this->Spec; }

  /// Moves the grid in space without touching the values (same node counts).
  void setGeometry(const std::array<double, D>& origin, const std::array<double, D>& spacing)
  {
    this->Spec.Origin = origin;
    this->Spec.Spacing = spacing;
  }
  int ghost() const { return this->Ghost; }
  const std::array<Index, D>& strides() const { return this->Stride; }

  /// Storage offset of node i (each i[a] in [-ghost, N + ghost)).
  Index offset(const std::array<Index, D>& i) const
  {
    Index o = this->Base;
    for (int a = 0; a < D; ++a)
    {
      o += i[a] * this->Stride[a];
    }
    return o;
  }

  T& operator()(const std::array<Index, D>& i) { return this->Values[static_cast<size_t>(this->offset(i))]; }
  const T& operator()(const std::array<Index, D>& i) const
  {
    return this->Values[static_cast<size_t>(this->offset(i))];
  }

  /// Pointer to node i (each i[a] in [-ghost, N + ghost)).
  T* pointer(const std::array<Index, D>& i) { return this->Values.data() + this->offset(i); }
  const T* pointer(const std::array<Index, D>& i) const { return this->Values.data() + this->offset(i); }

  /// Pointer to node (0,...,0); add offsets/strides to reach any node or ghost.
  T* origin() { return this->Values.data() + this->Base; }
  const T* origin() const { return this->Values.data() + this->Base; }

  /// Multi-index of the k-th interior node in x-fastest order, k in [0, nodeCount).
  std::array<Index, D> nodeIndex(Index k) const { return this->Indexer(k); }

  /// Fills all ghost layers from interior values, axis by axis (so corners
  /// are consistent): periodic copies, or linear extrapolation from the two
  /// nearest boundary nodes (u_{-k} = u_0 - k (u_1 - u_0)).
  void fillGhosts()
  {
    for (int a = 0; a < D; ++a)
    {
      this->fillGhostsAlong(a, 0, this->linesAlong(a));
    }
  }
  /// The same, each axis' lines shared out by `ctx.parallelFor(begin, end, body)`
  /// (a Context: the iterations' refills, every boundary line of a large grid).
  template <class Executor>
  void fillGhosts(const Executor& ctx)
  {
    for (int a = 0; a < D; ++a)
    {
      ctx.parallelFor(0, this->linesAlong(a), [&](Index b, Index e) { this->fillGhostsAlong(a, b, e); });
    }
  }

  std::vector<T>& storage() { return this->Values; }
  const std::vector<T>& storage() const { return this->Values; }

private:
  /// The spec, ghost layers, strides and base of a shape; returns its value count.
  Index setShape(const GridSpec<D>& spec, int ghost)
  {
    this->Spec = spec;
    this->Indexer = NodeIndexer<D>(spec.Dims);
    this->Ghost = ghost;
    Index total = 1;
    for (int a = 0; a < D; ++a)
    {
      this->Stride[a] = total;
      total *= spec.Dims[a] + 2 * ghost;
    }
    this->Base = 0;
    for (int a = 0; a < D; ++a)
    {
      this->Base += ghost * this->Stride[a];
    }
    return total;
  }

  /// Lines along `axis` in the padded box (the other axes include their ghosts).
  Index linesAlong(int axis) const
  {
    Index lines = 1;
    for (int a = 0; a < D; ++a)
    {
      lines *= a == axis ? 1 : this->Spec.Dims[a] + 2 * this->Ghost;
    }
    return lines;
  }

  /// The ghosts of the lines [first, last) along `axis` (linesAlong's order).
  void fillGhostsAlong(int axis, Index first, Index last)
  {
    const Index n = this->Spec.Dims[axis];
    const Index g = this->Ghost;
    std::array<Index, D> ext{};
    for (int a = 0; a < D; ++a)
    {
      ext[a] = a == axis ? 1 : this->Spec.Dims[a] + 2 * g;
    }
    const Index s = this->Stride[axis];
    // The first line's position by division, the next ones counted like an
    // odometer (a division per line cost more than the ghosts of a small block).
    std::array<Index, D> at{};
    Index rest = first;
    for (int a = 0; a < D; ++a)
    {
      at[a] = rest % ext[a];
      rest /= ext[a];
    }
    for (Index line = first; line < last; ++line)
    {
      if (line > first)
      {
        for (int a = 0; a < D && ++at[a] == ext[a]; ++a)
        {
          at[a] = 0;
        }
      }
      Index start = 0;
      for (int a = 0; a < D; ++a)
      {
        start += (a == axis ? g : at[a]) * this->Stride[a];
      }
      T* p = this->Values.data() + start; // node 0 of this line
      for (Index k = 1; k <= g; ++k)
      {
        if (this->Spec.Bounds[axis] == Boundary::Periodic)
        {
          p[-k * s] = p[((n - k % n) % n) * s];
          p[(n - 1 + k) * s] = p[((k - 1) % n) * s];
        }
        else
        {
          const T left = p[0] - p[s];
          const T right = p[(n - 1) * s] - p[(n - 2) * s];
          p[-k * s] = p[0] + T(k) * left;
          p[(n - 1 + k) * s] = p[(n - 1) * s] + T(k) * right;
        }
      }
    }
  }

  GridSpec<D> Spec{};
  NodeIndexer<D> Indexer{}; // nodeIndex() without a division per axis
  int Ghost = 0;
  std::array<Index, D> Stride{};
  Index Base = 0;
  std::vector<T> Values;
};

} // namespace sltk
