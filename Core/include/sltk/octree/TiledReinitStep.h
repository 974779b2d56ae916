// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TiledReinitStep.h
/// One Jacobi pseudo-time step of the reinitialisation (1.30) over marked
/// nodes of a TiledField (TiledReinitialise.h): (1.32)/(1.35) with the sign
/// (1.31) of phi0, or Russo-Smereka's (1.36) next to the front (1.38), from
/// the node's axis neighbours read straight from the tiles. The nodes run L
/// at a time, one per lane (Lanes.h; the schemes are ReinitScheme.h's
/// templates, so every lane is the scalar step's value bit for bit), in AVX2
/// when the processor has it.
///
/// A neighbour across a tile face is read through the face's entry: the
/// neighbouring tile, or a tile of the slot's constant value (+-gamma, NaN
/// for a Remote ghost), or beyond the grid's first node the node itself
/// (constant extension) or +gamma (as TiledField::scratch reads it).

#include "sltk/interp/Lanes.h"
#include "sltk/levelset/ReinitOptions.h"
#include "sltk/levelset/ReinitScheme.h"
#include "sltk/octree/TiledField.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

// The lanes' functions are always inlined, so the vector ABI never applies.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace sltk
{

template <int D>
class TiledReinitStep
{
public:
  /// A marked node: its tile and its index in the tile.
  struct Node
  {
    std::int32_t Tile;
    std::int32_t Local;
  };

  /// What a step reads besides the field: per marked node its coefficient
  /// (the sign s of (1.31), or the distance of (1.37) where Relax), whether
  /// it is Fixed (never stepped) or relaxed by (1.36).
  struct Band
  {
    const Node* Nodes = nullptr;
    const double* Coefficient = nullptr;
    const std::uint8_t* Fixed = nullptr;
    const std::uint8_t* Relax = nullptr;
  };

  /// Beyond the grid's first node: the node's own value (the pseudo-time
  /// steps) or +gamma (the classification, as TiledField::scratch).
  enum class Lower : std::uint8_t
  {
    Self,
    Gamma
  };

  /// Reads the field's tiles and their face neighbours: valid until tiles are
  /// added or removed.
  void prepare(TiledField<D>& field, Lower lower)
  {
    const std::array<double, 3> constants{ field.gamma(), -field.gamma(), std::numeric_limits<double>::quiet_NaN() };
    for (int k = 0; k < 3; ++k)
    {
      this->Constant[static_cast<size_t>(k)].assign(static_cast<size_t>(TiledField<D>::Nodes), constants[k]);
    }
    this->Tiles.resize(static_cast<size_t>(field.tileCount()));
    for (std::int32_t id = 0; id < field.tileCount(); ++id)
    {
      TileView& view = this->Tiles[static_cast<size_t>(id)];
      view.Phi = field.phi(id);
      for (int a = 0; a < D; ++a)
      {
        const Index across = (TileEdge - 1) * (Index(1) << (TileBits * a)); // the same node's place in the next tile
        for (int side = 0; side < 2; ++side)
        {
          auto t = field.tileOrigin(id);
          t[a] += side ? 1 : -1;
          std::int32_t entry = TiledField<D>::Outside;
          if (t[a] >= 0 && t[a] < field.slotDims()[a])
          {
            entry = field.slot(field.slotIndex(t));
          }
          Face& face = view.Faces[2 * a + side];
          face.Shift = entry >= 0 ? (side ? -across : across) : 0;
          face.Base = entry >= 0 ? field.phi(entry) : this->constant(entry);
          if (t[a] < 0 && lower == Lower::Self)
          {
            face.Base = view.Phi;
          }
        }
      }
    }
  }

  /// The values of the prepared tiles (for the copy back).
  double* phi(std::int32_t tile) const { return this->Tiles[static_cast<size_t>(tile)].Phi; }

  /// u = (node, then the lower and upper neighbour of every axis), as ReinitStencil::axes.
  SLTK_LANES_INLINE void axes(const Node& node, double* u) const
  {
    const TileView& view = this->Tiles[static_cast<size_t>(node.Tile)];
    const Index local = node.Local;
    u[0] = view.Phi[local];
    for (int a = 0; a < D; ++a)
    {
      u[1 + 2 * a] = *this->neighbour(view, local, a, 0);
      u[2 + 2 * a] = *this->neighbour(view, local, a, 1);
    }
  }

  /// Steps the nodes [b, e) of `band` into next[], returns their largest
  /// |change| (HUGE_VAL if a value is not finite): lanes, in AVX2 if the processor has it.
  double step(const Band& band, const ReinitOptions& options, double dtau, Index b, Index e, double* next) const
  {
    double largest = 0.0;
#if defined(SLTK_LANES_AVX2)
    const Index p = lanes::hasAvx2() ? this->stepAvx2(band, options, dtau, b, e, next, largest)
                                     : this->stepLanes<2>(band, options, dtau, b, e, next, largest);
#else
    const Index p = this->stepLanes<2>(band, options, dtau, b, e, next, largest);
#endif
    this->stepNodes(band, options, dtau, p, e, next, largest);
    return largest;
  }

  /// step() on two lanes (SSE2 pairs on x86-64), for the tests.
  double stepPairs(const Band& band, const ReinitOptions& options, double dtau, Index b, Index e, double* next) const
  {
    double largest = 0.0;
    const Index p = this->stepLanes<2>(band, options, dtau, b, e, next, largest);
    this->stepNodes(band, options, dtau, p, e, next, largest);
    return largest;
  }

  /// The nodes [b, e) one by one (the lanes' remainder; the tests' reference), largest |change| into `largest`.
  void stepNodes(
    const Band& band, const ReinitOptions& options, double dtau, Index b, Index e, double* next, double& largest) const
  {
    double u[1 + 2 * D];
    for (Index n = b; n < e; ++n)
    {
      if (band.Fixed[n])
      {
        continue;
      }
      this->axes(band.Nodes[n], u);
      const double c = band.Coefficient[n];
      double v = u[0];
      if (options.Method == ReinitMethod::RussoSmereka && band.Relax[n])
      {
        v = russoSmerekaStep(u[0], c, options.Courant); // (1.36)
      }
      else
      {
        v = reinitStep<D>(options.Scheme, u, this->InverseSpacing, c, dtau); // (1.32)/(1.35)
      }
      next[n] = v;
      largest = std::isfinite(v) ? std::max(largest, std::fabs(v - u[0])) : HUGE_VAL;
    }
  }

  /// The grid's inverse spacings (1.33).
  void setSpacing(const GridSpec<D>& grid)
  {
    for (int a = 0; a < D; ++a)
    {
      this->InverseSpacing[a] = 1.0 / grid.Spacing[a];
    }
  }

private:
  /// A face's neighbour of the node at `local`: Base[local + Shift].
  struct Face
  {
    const double* Base = nullptr;
    Index Shift = 0;
  };
  struct TileView
  {
    double* Phi = nullptr;
    Face Faces[2 * D];
  };

  const double* constant(std::int32_t entry) const
  {
    const int k = entry == TiledField<D>::Inside ? 1 : (entry == TiledField<D>::Remote ? 2 : 0);
    return this->Constant[static_cast<size_t>(k)].data();
  }

  /// Where the node at `local` of `view` finds its neighbour on `side` (0 lower, 1 upper) of axis a.
  static SLTK_LANES_INLINE const double* neighbour(const TileView& view, Index local, int a, int side)
  {
    const Index s = Index(1) << (TileBits * a);
    const Index c = (local >> (TileBits * a)) & (TileEdge - 1);
    const Face& face = view.Faces[2 * a + side];
    const bool inTile = side ? c < TileEdge - 1 : c > 0;
    return inTile ? view.Phi + local + (side ? s : -s) : face.Base + (local + face.Shift);
  }

  /// stepNodes() for [b, e) L nodes at a time, one per lane; returns where the groups stopped.
  template <int L>
  SLTK_LANES_INLINE Index stepLanes(
    const Band& band, const ReinitOptions& options, double dtau, Index b, Index e, double* next, double& largest) const
  {
    using Vec = lanes::Lanes<L>;
    using Mask = lanes::Mask<L>;
    const bool relaxing = options.Method == ReinitMethod::RussoSmereka;
    const Vec infinite = Vec{} + HUGE_VAL;
    const Vec finiteBound = Vec{} + std::numeric_limits<double>::max();
    Vec most{};
    Index n = b;
    for (; n + L <= e; n += L)
    {
      const Node* nodes = band.Nodes + n;
      const TileView* view[L];
      for (int l = 0; l < L; ++l)
      {
        view[l] = &this->Tiles[static_cast<size_t>(nodes[l].Tile)];
      }
      Vec u[1 + 2 * D];
      lanes::gatherOf<L>([&](int l) { return view[l]->Phi[nodes[l].Local]; }, u[0]);
      for (int a = 0; a < D; ++a)
      {
        for (int side = 0; side < 2; ++side)
        {
          lanes::gatherOf<L>([&](int l) { return *neighbour(*view[l], nodes[l].Local, a, side); }, u[1 + 2 * a + side]);
        }
      }
      Vec c;
      std::memcpy(&c, band.Coefficient + n, sizeof(Vec));
      Mask relax{};
      if (relaxing)
      {
        lanes::maskOf<L>([&](int l) { return band.Relax[n + l] != 0; }, relax);
      }
      Vec v; // (1.32)/(1.35), or (1.36) in the lanes of `relax`
      bandNodeStep<D>(
        options.Scheme, u, this->InverseSpacing, c, dtau, options.Courant, relaxing ? &relax : nullptr, v);
      Mask fixed;
      lanes::maskOf<L>([&](int l) { return band.Fixed[n + l] != 0; }, fixed);
      double each[L];
      std::memcpy(each, &v, sizeof(Vec));
      for (int l = 0; l < L; ++l)
      {
        next[n + l] = band.Fixed[n + l] ? next[n + l] : each[l]; // a fixed node's is never written
      }
      // std::max(most, |v - u|), HUGE_VAL where v is not finite, 0 where fixed (stepNodes).
      Vec moved, magnitude;
      lanes::absOf(v - u[0], moved);
      lanes::absOf(v, magnitude);
      moved = magnitude <= finiteBound ? moved : infinite;
      moved = fixed ? Vec{} : moved;
      most = most < moved ? moved : most;
    }
    double each[L];
    std::memcpy(each, &most, sizeof(Vec));
    for (int l = 0; l < L; ++l)
    {
      largest = std::max(largest, each[l]);
    }
    return n;
  }

#if defined(SLTK_LANES_AVX2)
  SLTK_LANES_AVX2_TARGET Index stepAvx2(
    const Band& band, const ReinitOptions& options, double dtau, Index b, Index e, double* next, double& largest) const
  {
    return this->stepLanes<4>(band, options, dtau, b, e, next, largest);
  }
#endif

  std::vector<TileView> Tiles;
  std::array<std::vector<double>, 3> Constant; ///< the tiles of +gamma, -gamma and NaN
  double InverseSpacing[D] = {};
};

} // namespace sltk

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
