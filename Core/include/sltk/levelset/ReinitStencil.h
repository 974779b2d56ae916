// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReinitStencil.h
/// Reads the nodal neighbourhoods the reinitialisation needs (thesis 1.5):
/// the 1 + 2D axis neighbours of a node (one-sided differences (1.33)) and
/// its 3^D block (central differences, curvature of (1.45), the set X of
/// (1.38)).
///
/// Nodes beyond the grid follow the grid's boundary policy computed from the
/// current interior values (periodic wrap, or the linear extrapolation that
/// GridField::fillGhosts() writes, u_{-k} = u_0 + k (u_0 - u_1); axes() uses a
/// zero slope instead, see there), so the ghost layers are never read and may
/// be stale or absent: the band values change at every pseudo-time step while
/// the ghosts would not.

#include "sltk/grid/GridField.h"

#include <array>

namespace sltk
{

template <int D>
class ReinitStencil
{
public:
  static constexpr int BlockSize = D == 1 ? 3 : (D == 2 ? 9 : 27); ///< 3^D
  static constexpr int Centre = (BlockSize - 1) / 2;               ///< block index of the node
  static constexpr int AxisSize = 1 + 2 * D;                       ///< node + axis neighbours

  explicit ReinitStencil(const GridField<D>& field)
    : Field(&field)
  {
  }

  /// Block index step along an axis: 3^axis.
  static constexpr int blockStride(int axis) { return axis == 0 ? 1 : 3 * blockStride(axis - 1); }

  const GridSpec<D>& spec() const { return this->Field->spec(); }

  /// Multi-index of interior node k (x fastest).
  std::array<Index, D> node(Index k) const { return this->Field->nodeIndex(k); }

  /// True when every node of the 3^D block of i is an interior node reached without wrap.
  bool interior(const std::array<Index, D>& i) const
  {
    for (int a = 0; a < D; ++a)
    {
      if (i[a] < 1 || i[a] > this->spec().Dims[a] - 2)
      {
        return false;
      }
    }
    return true;
  }

  /// Value at node i + o (o[a] in {-1, 0, 1}; i + o may lie beyond the grid).
  double at(const std::array<Index, D>& i, const std::array<int, D>& o) const
  {
    const GridSpec<D>& g = this->spec();
    // Per axis, the node is a combination of at most two interior nodes.
    Index index[D][2];
    double weight[D][2];
    for (int a = 0; a < D; ++a)
    {
      const Index n = g.Dims[a];
      const Index j = i[a] + o[a];
      index[a][1] = 0;
      weight[a][1] = 0.0;
      if (j >= 0 && j < n)
      {
        index[a][0] = j;
        weight[a][0] = 1.0;
      }
      else if (g.Bounds[a] == Boundary::Periodic)
      {
        index[a][0] = ((j % n) + n) % n;
        weight[a][0] = 1.0;
      }
      else
      {
        // Linear extrapolation from the two nearest boundary nodes.
        const Index k = j < 0 ? -j : j - (n - 1);
        index[a][0] = j < 0 ? 0 : n - 1;
        index[a][1] = j < 0 ? 1 : n - 2;
        weight[a][0] = 1.0 + static_cast<double>(k);
        weight[a][1] = -static_cast<double>(k);
      }
    }
    double sum = 0.0;
    for (int c = 0; c < (1 << D); ++c)
    {
      double w = 1.0;
      std::array<Index, D> m{};
      for (int a = 0; a < D; ++a)
      {
        const int t = (c >> a) & 1;
        w *= weight[a][t];
        m[a] = index[a][t];
      }
      if (w != 0.0)
      {
        sum += w * (*this->Field)(m);
      }
    }
    return sum;
  }

  /// u[0] = node i, u[1 + 2a] = i - e_a, u[2 + 2a] = i + e_a, for the one-sided
  /// differences (1.33) of the pseudo-time steps. Beyond an extrapolated grid
  /// end the neighbour takes the node's own value: the one-sided difference
  /// across the end is 0 and never upwind, so the grid end brings no
  /// information. Where the characteristics leave the grid this changes
  /// nothing (the interior side is upwind); where they enter it (the front
  /// leaves the grid) the distance depends on front that is not there, and any
  /// extrapolation of the node's own neighbours (the ghost rule
  /// u_{-1} = 2 u_0 - u_1, or continuing the slope u_{-1} = u_0 - (u_2 - u_1))
  /// turns the explicit step into a downwind one that grows by 1 + O(dtau/dx)
  /// per step. There the scheme is stable but the result is not a distance
  /// (without upwind data |phi| grows by up to dtau per step).
  void axes(const std::array<Index, D>& i, double* u) const
  {
    if (this->interior(i))
    {
      this->axesInterior(this->Field->pointer(i), u);
      return;
    }
    const GridSpec<D>& g = this->spec();
    u[0] = (*this->Field)(i);
    for (int a = 0; a < D; ++a)
    {
      for (int side = -1; side <= 1; side += 2)
      {
        std::array<Index, D> j = i;
        j[a] += side;
        double value = u[0];
        if (j[a] >= 0 && j[a] < g.Dims[a])
        {
          value = (*this->Field)(j);
        }
        else if (g.Bounds[a] == Boundary::Periodic)
        {
          j[a] = (j[a] + g.Dims[a]) % g.Dims[a];
          value = (*this->Field)(j);
        }
        u[side < 0 ? 1 + 2 * a : 2 + 2 * a] = value;
      }
    }
  }

  /// axes() of an interior node (interior(i) true) given its storage pointer.
  void axesInterior(const double* p, double* u) const
  {
    const auto& s = this->Field->strides();
    u[0] = p[0];
    for (int a = 0; a < D; ++a)
    {
      u[1 + 2 * a] = p[-s[a]];
      u[2 + 2 * a] = p[s[a]];
    }
  }

  /// u[sum_a (o_a + 1) 3^a] = node i + o for o in {-1, 0, 1}^D.
  void block(const std::array<Index, D>& i, double* u) const
  {
    if (this->interior(i))
    {
      this->blockInterior(this->Field->pointer(i), u);
      return;
    }
    for (int c = 0; c < BlockSize; ++c)
    {
      std::array<int, D> o{};
      int rest = c;
      for (int a = 0; a < D; ++a)
      {
        o[a] = rest % 3 - 1;
        rest /= 3;
      }
      u[c] = this->at(i, o);
    }
  }

  /// block() of an interior node (interior()) at `p`: plain reads, x fastest.
  void blockInterior(const double* p, double* u) const
  {
    const auto& s = this->Field->strides();
    int c = 0;
    if constexpr (D == 1)
    {
      for (int x = -1; x <= 1; ++x)
      {
        u[c++] = p[x * s[0]];
      }
    }
    else if constexpr (D == 2)
    {
      for (int y = -1; y <= 1; ++y)
      {
        for (int x = -1; x <= 1; ++x)
        {
          u[c++] = p[y * s[1] + x * s[0]];
        }
      }
    }
    else
    {
      for (int z = -1; z <= 1; ++z)
      {
        for (int y = -1; y <= 1; ++y)
        {
          for (int x = -1; x <= 1; ++x)
          {
            u[c++] = p[z * s[2] + y * s[1] + x * s[0]];
          }
        }
      }
    }
  }

private:
  const GridField<D>* Field;
};

} // namespace sltk
