// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TiledReinitialise.h (private)
/// The uniform version's narrow-band reinitialisation (Reinitialise.h: the
/// constrained explicit values (1.38)-(1.45) on the nodes next to the front,
/// then Jacobi pseudo-time steps of (1.30) with the sign (1.31) of phi0) on a
/// TiledField, with the same kernels (ReinitInterface.h, ReinitScheme.h): the
/// nodes are classified tile by tile from their axis neighbours, those next to
/// the front on a copy of the tile with two nodes around it, and every
/// pseudo-time step reads the axis neighbours straight from the tiles, nodes
/// in SIMD lanes (TiledReinitStep.h). The band is the band before the step dilated (1.53), as in
/// the uniform version; the values are cut at +-gamma (1.49) afterwards.
/// Distributed (TileDistribution.h), each rank updates the nodes of its own
/// tiles and its ghosts' values follow every pseudo-time step.

#include "TileDistribution.h"
#include "sltk/exec/Context.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/levelset/ReinitInterface.h"
#include "sltk/levelset/ReinitOptions.h"
#include "sltk/octree/TiledField.h"
#include "sltk/octree/TiledReinitStep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sltk
{

template <int D>
class TiledReinitialiser
{
public:
  /// The nodes to reinitialise: those of `band`'s tiles with |phi| < gamma
  /// and every node within `dilation` of one (1.53), in the tiles this rank
  /// owns (`band`: every held tile with a band node, ghosts included); their
  /// values now are phi^n of eps_1 (4.34).
  void markBand(const TiledField<D>& field, const std::vector<std::int32_t>& band, int dilation, const Context& ctx,
    const TileDistribution<D>& distribution)
  {
    const Index nodes = TiledField<D>::Nodes;
    this->Mask.assign(static_cast<size_t>(field.tileCount() * nodes), 0);
    std::vector<std::array<Index, D>> ball;
    for (Index o = 0; o < ipow3(2 * dilation + 1); ++o)
    {
      std::array<Index, D> v{};
      Index rest = o, r2 = 0;
      for (int a = 0; a < D; ++a)
      {
        v[a] = rest % (2 * dilation + 1) - dilation;
        rest /= 2 * dilation + 1;
        r2 += v[a] * v[a];
      }
      if (r2 <= dilation * dilation)
      {
        ball.push_back(v);
      }
    }
    std::vector<Index> ballOffsets; // the ball's offsets within one tile
    for (const auto& v : ball)
    {
      Index offset = 0;
      for (int a = 0; a < D; ++a)
      {
        offset += v[a] * (Index(1) << (TileBits * a));
      }
      ballOffsets.push_back(offset);
    }
    // Serial: neighbouring tiles share mask entries.
    for (std::int32_t id : band)
    {
      const double* p = field.phi(id);
      for (Index k = 0; k < nodes; ++k)
      {
        if (!(std::fabs(p[k]) < field.gamma()))
        {
          continue;
        }
        bool interior = true; // the whole ball inside this tile
        for (int a = 0; a < D; ++a)
        {
          const Index c = (k >> (TileBits * a)) & (TileEdge - 1);
          interior = interior && c >= dilation && c < TileEdge - dilation;
        }
        if (interior)
        {
          for (Index offset : ballOffsets)
          {
            this->Mask[static_cast<size_t>(id * nodes + k + offset)] = 1;
          }
          continue;
        }
        const auto i = field.node(id, k);
        for (const auto& v : ball)
        {
          std::array<Index, D> j = i;
          for (int a = 0; a < D; ++a)
          {
            j[a] += v[a];
          }
          Index local = 0;
          const std::int32_t tile = tileOf(field, j, local);
          if (tile >= 0)
          {
            this->Mask[static_cast<size_t>(tile * nodes + local)] = 1;
          }
        }
      }
    }
    this->Nodes.clear();
    this->Nodes.shrink_to_fit();
    this->Nodes.reserve(static_cast<size_t>(std::count(this->Mask.begin(), this->Mask.end(), std::uint8_t(1))));
    // Tile after tile in slot order, so that eps_1's sums do not depend on the tiles' ids.
    field.forEachTileInSlotOrder(
      [&](std::int32_t id)
      {
        if (!distribution.owns(field, id))
        {
          return;
        }
        for (Index k = 0; k < nodes; ++k)
        {
          if (this->Mask[static_cast<size_t>(id * nodes + k)])
          {
            this->Nodes.push_back({ id, static_cast<std::int32_t>(k) });
          }
        }
      });
    this->Before.resize(this->Nodes.size());
    ctx.parallelFor(0, static_cast<Index>(this->Nodes.size()),
      [&](Index b, Index e)
      {
        for (Index n = b; n < e; ++n)
        {
          const Node& node = this->Nodes[static_cast<size_t>(n)];
          this->Before[static_cast<size_t>(n)] = field.phi(node.Tile)[node.Local];
        }
      });
  }

  /// Reinitialises and cuts the marked nodes (collective when distributed:
  /// every rank returns the same status).
  Status run(TiledField<D>& field, const ReinitOptions& options, const Context& ctx, TileDistribution<D>& distribution)
  {
    SLTK_RETURN_IF_ERROR(options.template validate<D>());
    const GridSpec<D>& g = field.grid();
    double h = g.Spacing[0];
    for (int a = 0; a < D; ++a)
    {
      this->Spacing[a] = g.Spacing[a];
      this->InverseSpacing[a] = 1.0 / g.Spacing[a];
      h = std::min(h, g.Spacing[a]);
    }
    const size_t count = this->Nodes.size();
    this->Fixed.assign(count, 0);
    this->Coefficient.resize(count); // every node's set by classify()
    this->Next.resize(count);        // every node's but the fixed ones' set by a step, then read
    this->ChunkChange.assign(
      static_cast<size_t>(std::max<Index>(1, ThreadPool::chunkCount(0, static_cast<Index>(count), ChangeGrain))), 0.0);
    this->Stepper.setSpacing(g);
    this->Stepper.prepare(field, Step::Lower::Gamma); // as TiledField::scratch reads beyond the grid
    this->classify(field, options, ctx);
    this->Stepper.prepare(field, Step::Lower::Self);
    for (size_t n = 0; n < count; ++n)
    {
      if (this->Fixed[n])
      {
        this->Stepper.phi(this->Nodes[n].Tile)[this->Nodes[n].Local] = this->Coefficient[n]; // the one step procedure
      }
    }
    distribution.exchangeFaces(field);       // the pseudo-time steps read the ghosts' faces only
    const double dtau = options.Courant * h; // (1.34)
    const typename Step::Band band{ this->Nodes.data(), this->Coefficient.data(), this->Fixed.data(),
      this->Relax.data() };
    for (int iteration = 1; iteration <= options.MaxIterations; ++iteration)
    {
      // The largest change, as the uniform version's BandSolver::step: the chunks' maxima, then
      // their maximum (independent of how the nodes fall into chunks).
      ctx.parallelFor(
        0, static_cast<Index>(count),
        [&](Index b, Index e)
        {
          this->ChunkChange[static_cast<size_t>(b / ChangeGrain)] =
            this->Stepper.step(band, options, dtau, b, e, this->Next.data()); // (1.32)/(1.35), (1.36)
        },
        ChangeGrain);
      const double change = distribution.max(*std::max_element(this->ChunkChange.begin(), this->ChunkChange.end()));
      ctx.parallelFor(0, static_cast<Index>(count),
        [&](Index b, Index e)
        {
          for (Index n = b; n < e; ++n)
          {
            if (!this->Fixed[static_cast<size_t>(n)])
            {
              const Node& node = this->Nodes[static_cast<size_t>(n)];
              this->Stepper.phi(node.Tile)[node.Local] = this->Next[static_cast<size_t>(n)];
            }
          }
        });
      distribution.exchangeFaces(field);
      if (!std::isfinite(change))
      {
        return Status::numericalFailure(
          "reinitialisation produced a non-finite value at pseudo-time step " + std::to_string(iteration));
      }
      if (change < options.Tolerance * h)
      {
        break;
      }
    }
    // Cut (1.49) and eps_1 (4.34) over the marked nodes: tile by tile, the
    // tiles added in slot order on any number of ranks.
    std::vector<KeyedSums<2>> tiles;
    for (size_t n = 0; n < count; ++n)
    {
      if (n == 0 || this->Nodes[n].Tile != this->Nodes[n - 1].Tile)
      {
        tiles.push_back({ static_cast<std::uint64_t>(field.tileSlot(this->Nodes[n].Tile)), {} });
      }
      double& v = field.phi(this->Nodes[n].Tile)[this->Nodes[n].Local];
      v = std::min(field.gamma(), std::max(-field.gamma(), v));
      tiles.back().Values[0] += std::fabs(v - this->Before[n]);
      tiles.back().Values[1] += std::fabs(this->Before[n]);
    }
    distribution.exchange(field, false); // whole ghost tiles: the next iteration reads them all
    const std::array<double, 2> sums = distribution.orderedSum(std::move(tiles), std::array<double, 2>{});
    this->Change = sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
    return Status::ok();
  }

  /// eps_1 (4.34) of the last run(): sum |phi^{n+1} - phi^n| / sum |phi^n| over the marked nodes.
  double relativeChange() const { return this->Change; }

private:
  using Step = TiledReinitStep<D>;
  using Node = typename Step::Node;

  static Index ipow3(Index n)
  {
    Index r = 1;
    for (int a = 0; a < D; ++a)
    {
      r *= n;
    }
    return r;
  }

  /// The tile holding grid index j (-1: none) and j's index in it.
  static std::int32_t tileOf(const TiledField<D>& field, const std::array<Index, D>& j, Index& local)
  {
    std::array<Index, D> t{};
    local = 0;
    for (int a = 0; a < D; ++a)
    {
      if (j[a] < 0 || (j[a] >> TileBits) >= field.slotDims()[a])
      {
        return -1;
      }
      t[a] = j[a] >> TileBits;
      local |= (j[a] & (TileEdge - 1)) << (TileBits * a);
    }
    return field.slot(field.slotIndex(t));
  }

  /// Role and coefficient of every marked node from phi0 (BandSolver::classify of Reinitialise.cxx).
  void classify(const TiledField<D>& field, const ReinitOptions& options, const Context& ctx)
  {
    this->Relax.assign(this->Nodes.size(), 0);
    // Marked nodes come tile by tile.
    std::vector<size_t> starts;
    for (size_t n = 0; n < this->Nodes.size(); ++n)
    {
      if (n == 0 || this->Nodes[n].Tile != this->Nodes[n - 1].Tile)
      {
        starts.push_back(n);
      }
    }
    starts.push_back(this->Nodes.size());
    double h = this->Spacing[0];
    for (int a = 1; a < D; ++a)
    {
      h = std::min(h, this->Spacing[a]);
    }
    ctx.parallelFor(
      0, static_cast<Index>(starts.size()) - 1,
      [&](Index b, Index e)
      {
        GridField<D> block;
        std::vector<size_t> near;
        for (Index r = b; r < e; ++r)
        {
          this->classifyTile(
            field, options, starts[static_cast<size_t>(r)], starts[static_cast<size_t>(r) + 1], h, block, near);
        }
      },
      8);
  }

  /// classify() of the marked nodes [b, e) of one tile: the axis neighbours
  /// decide (1.38) and give (1.31), read from the tiles (prepared with +gamma
  /// beyond the grid, as the copy reads it); only if some are next to the
  /// front, a copy of the tile with two nodes around it gives their 3^D blocks.
  void classifyTile(const TiledField<D>& field, const ReinitOptions& options, size_t b, size_t e, double h,
    GridField<D>& block, std::vector<size_t>& near)
  {
    near.clear();
    double axes[ReinitStencil<D>::AxisSize];
    for (size_t n = b; n < e; ++n)
    {
      this->Stepper.axes(this->Nodes[n], axes);
      if (options.Method != ReinitMethod::Plain && axesAdjacentToInterface<D>(axes)) // (1.38)
      {
        near.push_back(n);
        continue;
      }
      this->Coefficient[n] = reinitSign(axes[0], axesCentralGradientNorm<D>(axes, this->InverseSpacing), h); // (1.31)
    }
    if (near.empty())
    {
      return;
    }
    constexpr int Halo = 2;
    field.scratch(this->Nodes[b].Tile, Halo, 0, block, nullptr); // ReinitStencil reads no ghost layers
    const ReinitStencil<D> stencil(block);
    double u[ReinitStencil<D>::BlockSize];
    for (size_t n : near)
    {
      std::array<Index, D> i{};
      for (int a = 0; a < D; ++a)
      {
        i[a] = Halo + ((this->Nodes[n].Local >> (TileBits * a)) & (TileEdge - 1));
      }
      stencil.block(i, u);
      if (options.Method == ReinitMethod::Constrained)
      {
        this->Fixed[n] = 1;
        this->Coefficient[n] = constrainedDistance<D>(stencil, i, u, this->InverseSpacing, this->Spacing); // (1.44)
      }
      else
      {
        this->Relax[n] = 1;
        this->Coefficient[n] = interfaceDistance<D>(u, this->InverseSpacing, this->Spacing); // (1.37)
      }
    }
  }

  std::vector<std::uint8_t> Mask;
  std::vector<Node> Nodes;
  Step Stepper;
  static constexpr Index ChangeGrain = 2048; ///< nodes a chunk of the largest change
  std::vector<double> Before, Coefficient, Next, ChunkChange;
  std::vector<std::uint8_t> Fixed, Relax;
  double Spacing[D] = {};
  double InverseSpacing[D] = {};
  double Change = 0.0;
};

} // namespace sltk
