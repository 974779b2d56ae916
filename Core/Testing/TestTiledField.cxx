// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/octree/TiledField.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
double linear(const std::array<sltk::Index, 3>& i)
{
  return static_cast<double>(i[0] + 100 * i[1] + 10000 * i[2]);
}
} // namespace

TEST(TiledField, ScratchCopiesTilesAndSidesAtAnyHalo)
{
  sltk::GridSpec<3> grid;
  grid.Dims = { 40, 24, 20 }; // 5 x 3 x 3 slots (the last ones partly beyond the grid)
  grid.Spacing = { 0.5, 0.5, 0.5 };
  grid.Origin = { -1.0, 2.0, 3.0 };
  sltk::TiledField<3> field;
  field.reset(grid, 1e6);
  ASSERT_EQ(field.slotDims(), (std::array<sltk::Index, 3>{ 5, 3, 3 }));
  // Tiles in a row along x at slot (y, z) = (0, 1); slot (1, 0, 2) inside; the rest outside.
  std::int32_t first = -1;
  for (sltk::Index x = 0; x < 4; ++x)
  {
    const std::int32_t id = field.addTile(field.slotIndex({ x, 0, 1 }));
    first = first < 0 ? id : first;
    for (sltk::Index k = 0; k < sltk::TiledField<3>::Nodes; ++k)
    {
      field.phi(id)[k] = linear(field.node(id, k));
      field.distance(id)[k] = 1.0;
    }
  }
  field.setSide(field.slotIndex({ 1, 0, 2 }), true);
  EXPECT_EQ(field.tileCount(), 4);
  for (int halo : { 1, 4, 8, 12, 20, 60 }) // 60: a row wider than MaxScratchSegments tiles (the heap path)
  {
    sltk::GridField<3> phi, dist;
    field.scratch(first + 1, halo, 2, phi, &dist); // tile (1, 0, 1): the halo reaches negative y
    const auto& o = field.tileOrigin(first + 1);
    for (sltk::Index k = 0; k < phi.spec().nodeCount(); ++k)
    {
      const auto b = phi.nodeIndex(k);
      std::array<sltk::Index, 3> g{};
      std::array<sltk::Index, 3> t{};
      bool beyond = false;
      for (int a = 0; a < 3; ++a)
      {
        g[a] = o[a] * sltk::TileEdge - halo + b[a];
        t[a] = g[a] >= 0 ? g[a] / sltk::TileEdge : -1 - (-g[a] - 1) / sltk::TileEdge;
        beyond = beyond || g[a] < 0 || t[a] >= field.slotDims()[a];
      }
      const bool tile = !beyond && t[1] == 0 && t[2] == 1 && t[0] < 4;
      const bool inside = !beyond && t[0] == 1 && t[1] == 0 && t[2] == 2;
      const double expected = tile ? linear(g) : (inside ? -1e6 : 1e6);
      ASSERT_EQ(phi(b), expected) << "halo " << halo << " node " << g[0] << " " << g[1] << " " << g[2];
      if (tile)
      {
        ASSERT_EQ(dist(b), 1.0);
      }
      else
      {
        ASSERT_TRUE(std::isnan(dist(b))); // no tile: no distance stored
      }
      ASSERT_EQ(field.value(g), expected);
    }
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_DOUBLE_EQ(phi.spec().Origin[a], grid.coordinate(a, o[a] * sltk::TileEdge - halo));
    }
  }
}

TEST(TiledField, ScratchBlockCopiesSeveralTilesAtOnce)
{
  sltk::GridSpec<3> grid;
  grid.Dims = { 40, 24, 20 };
  grid.Spacing = { 0.5, 0.5, 0.5 };
  grid.Origin = { -1.0, 2.0, 3.0 };
  sltk::TiledField<3> field;
  field.reset(grid, 1e6);
  // Tiles on a diagonal, sides alternating around them.
  for (sltk::Index x = 0; x < 3; ++x)
  {
    const std::int32_t id = field.addTile(field.slotIndex({ x + 1, x, x }));
    for (sltk::Index k = 0; k < sltk::TiledField<3>::Nodes; ++k)
    {
      field.phi(id)[k] = linear(field.node(id, k));
      field.distance(id)[k] = 2.0;
    }
  }
  field.setSide(field.slotIndex({ 2, 1, 2 }), true);
  const std::array<sltk::Index, 3> first{ 1, 0, 0 };
  for (int halo : { 0, 3, 9 })
  {
    sltk::GridField<3> phi, dist;
    field.scratchBlock(first, 2, halo, 1, phi, &dist);
    ASSERT_EQ(phi.spec().Dims[0], 2 * sltk::TileEdge + 2 * halo);
    for (sltk::Index k = 0; k < phi.spec().nodeCount(); ++k)
    {
      const auto b = phi.nodeIndex(k);
      std::array<sltk::Index, 3> g{};
      for (int a = 0; a < 3; ++a)
      {
        g[a] = first[a] * sltk::TileEdge - halo + b[a];
      }
      ASSERT_EQ(phi(b), field.value(g)) << "halo " << halo << " node " << g[0] << " " << g[1] << " " << g[2];
      const bool stored = field.value(g) != 1e6 && field.value(g) != -1e6;
      ASSERT_TRUE(stored ? dist(b) == 2.0 : std::isnan(dist(b)));
    }
  }
}

TEST(TiledField, ScratchBlockCopiesTheDistanceNearTheBlockOnlyWhenAsked)
{
  sltk::GridSpec<3> grid;
  grid.Dims = { 40, 24, 20 };
  grid.Spacing = { 0.5, 0.5, 0.5 };
  sltk::TiledField<3> field;
  field.reset(grid, 1e6);
  for (sltk::Index x = 0; x < 3; ++x)
  {
    const std::int32_t id = field.addTile(field.slotIndex({ x, x % 2, 1 }));
    for (sltk::Index k = 0; k < sltk::TiledField<3>::Nodes; ++k)
    {
      field.phi(id)[k] = linear(field.node(id, k));
      field.distance(id)[k] = static_cast<double>(k + 100 * id);
    }
  }
  const std::array<sltk::Index, 3> first{ 1, 0, 1 };
  for (int halo : { 3, 9 })
  {
    sltk::GridField<3> phi, dist, fullPhi, fullDist;
    field.scratchBlock(first, 2, halo, 1, fullPhi, &fullDist);
    field.scratchBlock(first, 2, halo, 1, phi, &dist); // the same shape: its values then marked
    for (sltk::Index k = 0; k < dist.spec().nodeCount(); ++k)
    {
      dist(dist.nodeIndex(k)) = -7.0;
    }
    field.scratchBlock(first, 2, halo, 1, phi, &dist, 1);
    const sltk::Index edge = 2 * sltk::TileEdge + 2 * halo;
    sltk::Index copied = 0;
    for (sltk::Index k = 0; k < dist.spec().nodeCount(); ++k)
    {
      const auto b = dist.nodeIndex(k);
      bool near = true; // within one node of the block's tiles
      for (int a = 0; a < 3; ++a)
      {
        near = near && b[a] >= halo - 1 && b[a] < edge - halo + 1;
      }
      ASSERT_EQ(phi(b), fullPhi(b)) << "phi is copied whole";
      const double full = fullDist(b);
      ASSERT_TRUE(near ? (dist(b) == full || (std::isnan(dist(b)) && std::isnan(full))) : dist(b) == -7.0)
        << "halo " << halo << " node " << b[0] << " " << b[1] << " " << b[2];
      copied += near ? 1 : 0;
    }
    EXPECT_EQ(copied, (edge - 2 * halo + 2) * (edge - 2 * halo + 2) * (edge - 2 * halo + 2));
  }
  // A halo no wider than distHalo: d copied whole, its ghost layers filled, as without it.
  sltk::GridField<3> phi, dist, fullPhi, fullDist;
  field.scratchBlock(first, 2, 1, 1, fullPhi, &fullDist);
  field.scratchBlock(first, 2, 1, 1, phi, &dist, 1);
  ASSERT_EQ(dist.storage().size(), fullDist.storage().size());
  for (size_t k = 0; k < dist.storage().size(); ++k)
  {
    const double a = dist.storage()[k], b = fullDist.storage()[k];
    ASSERT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << "storage index " << k;
  }
}

TEST(TiledField, FlatCellsAreLeavesOfTheTilesOctree)
{
  sltk::GridSpec<3> grid;
  grid.Dims = { 16, 16, 13 }; // the tiles of the second slot layer stop at node 12
  grid.Spacing = { 1.0, 1.0, 1.0 };
  const double gamma = 3.0;
  sltk::TiledField<3> field;
  field.reset(grid, gamma);
  const std::int32_t inside = field.addTile(field.slotIndex({ 0, 0, 0 }));
  const std::int32_t last = field.addTile(field.slotIndex({ 1, 1, 1 }));
  for (const std::int32_t id : { inside, last })
  {
    std::fill_n(field.phi(id), sltk::TiledField<3>::Nodes, gamma);
  }
  EXPECT_TRUE(field.flatCell(inside, { 0, 0, 0 }, sltk::TileEdge));
  EXPECT_EQ(field.leafCount(inside), 1) << "a tile at +gamma throughout is one leaf";
  field.phi(inside)[0] = 0.5; // node (0, 0, 0) near the front
  EXPECT_FALSE(field.flatCell(inside, { 0, 0, 0 }, sltk::TileEdge));
  EXPECT_TRUE(field.flatCell(inside, { 4, 0, 0 }, 4));
  // The root's 7 flat children, the first child's 7, and its first child's 8 nodes.
  EXPECT_EQ(field.leafCount(inside), 7 + 7 + 8);
  field.phi(inside)[0] = -gamma; // both sides in one cell: not flat
  EXPECT_FALSE(field.flatCell(inside, { 0, 0, 0 }, 2));
  EXPECT_EQ(field.leafCount(inside), 7 + 7 + 8);
  // Nodes 13..15 along z lie beyond the grid: the cells holding them are refined, and the
  // cells wholly beyond are no leaves (masked in the output). Along z: nodes 8..12 in the grid.
  EXPECT_FALSE(field.flatCell(last, { 0, 0, 0 }, sltk::TileEdge));
  EXPECT_TRUE(field.flatCell(last, { 0, 0, 0 }, 4));  // nodes 8..11 along z
  EXPECT_FALSE(field.flatCell(last, { 0, 0, 4 }, 4)); // nodes 12..15
  // The 4 lower children (flat), and of each upper child its 4 lower children of 2^3 nodes
  // (12..13 along z: not flat, 13 beyond), whose 4 lower nodes (z = 12) are leaves.
  EXPECT_EQ(field.leafCount(last), 4 + 4 * 4 * 4);
}

TEST(TiledField, RemovedTilesBecomeTheirSideAndTheOthersKeepTheirValues)
{
  sltk::GridSpec<3> grid;
  grid.Dims = { 48, 48, 48 };
  grid.Spacing = { 1.0, 1.0, 1.0 };
  sltk::TiledField<3> field;
  const double gamma = 3.0;
  field.reset(grid, gamma);
  // 200 tiles (more than three chunks of 64): even ids removed, at -gamma or +gamma by id.
  std::vector<std::uint8_t> remove;
  for (sltk::Index s = 0; s < 200; ++s)
  {
    const std::int32_t id = field.addTile(s);
    const bool removed = id % 2 == 0;
    remove.push_back(removed ? 1 : 0);
    for (sltk::Index k = 0; k < sltk::TiledField<3>::Nodes; ++k)
    {
      field.phi(id)[k] = removed ? (id % 4 == 0 ? -gamma : gamma) : linear(field.node(id, k));
      field.distance(id)[k] = static_cast<double>(id);
    }
  }
  const double before = field.bytes();
  field.removeTiles(remove);
  ASSERT_EQ(field.tileCount(), 100);
  EXPECT_LT(field.bytes(), before); // two of the four chunks freed
  for (sltk::Index s = 0; s < 200; ++s)
  {
    const std::int32_t id = field.slot(s);
    if (s % 2 == 0)
    {
      EXPECT_EQ(id, s % 4 == 0 ? sltk::TiledField<3>::Inside : sltk::TiledField<3>::Outside) << "slot " << s;
      continue;
    }
    ASSERT_EQ(id, s / 2) << "the kept tiles keep their order";
    EXPECT_EQ(field.tileSlot(id), s);
    EXPECT_EQ(field.tileOrigin(id), field.slotCoordinates(s));
    for (sltk::Index k = 0; k < sltk::TiledField<3>::Nodes; ++k)
    {
      ASSERT_EQ(field.phi(id)[k], linear(field.node(id, k)));
      ASSERT_EQ(field.distance(id)[k], static_cast<double>(s));
    }
  }
  // A removed slot takes a tile again at its side's value.
  const std::int32_t again = field.addTile(0);
  EXPECT_EQ(again, 100);
  EXPECT_EQ(field.phi(again)[17], -gamma);
  EXPECT_TRUE(std::isnan(field.distance(again)[17]));
}
