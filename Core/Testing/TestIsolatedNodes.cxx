// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/levelset/IsolatedNodes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// phi of a ball of radius r around the origin (negative inside) on a 3D grid.
sltk::GridField<3> ballField(const sltk::GridSpec<3>& g, double r)
{
  sltk::GridField<3> phi(g, 1);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = phi.nodeIndex(k);
    double s = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      s += g.coordinate(a, i[a]) * g.coordinate(a, i[a]);
    }
    phi(i) = std::sqrt(s) - r;
  }
  phi.fillGhosts();
  return phi;
}

sltk::NodeList everyNode(const sltk::GridSpec<3>& g)
{
  sltk::NodeList nodes(static_cast<size_t>(g.nodeCount()));
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    nodes[static_cast<size_t>(k)] = k;
  }
  return nodes;
}
} // namespace

// A positive node inside the ball (a bubble) and a negative one outside (a
// speck) are given their neighbours' mean; a smooth ball has none, and a
// two-node speck is a feature the grid can carry: it stays.
TEST(IsolatedNodes, SingleNodeSpecksAreMergedAndNothingElse)
{
  const auto g = sltk::uniformBox<3>(21, -1.0, 1.0); // dx 0.1
  sltk::GridField<3> phi = ballField(g, 0.5);
  std::vector<sltk::NodeChange> changes;
  sltk::findIsolatedNodes(phi, everyNode(g), changes);
  EXPECT_TRUE(changes.empty());

  const std::array<sltk::Index, 3> bubble{ 10, 10, 10 }, speck{ 2, 10, 10 }, pairA{ 10, 2, 10 }, pairB{ 10, 3, 10 };
  const std::array<sltk::Index, 3> edge{ 0, 10, 10 };
  phi(bubble) = 0.05;
  phi(speck) = -0.01;
  phi(pairA) = phi(pairB) = -0.01;
  phi(edge) = -0.01; // on the grid's boundary: left alone
  sltk::findIsolatedNodes(phi, everyNode(g), changes);
  ASSERT_EQ(changes.size(), 2u);
  double bubbleMean = 0.0, speckMean = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    for (const int side : { -1, 1 })
    {
      auto n = bubble, m = speck;
      n[static_cast<size_t>(a)] += side;
      m[static_cast<size_t>(a)] += side;
      bubbleMean += phi(n) / 6.0;
      speckMean += phi(m) / 6.0;
    }
  }
  sltk::applyNodeChanges(phi, changes);
  EXPECT_DOUBLE_EQ(phi(bubble), bubbleMean);
  EXPECT_LT(phi(bubble), 0.0);
  EXPECT_DOUBLE_EQ(phi(speck), speckMean);
  EXPECT_GT(phi(speck), 0.0);
  EXPECT_EQ(phi(pairA), -0.01);
  EXPECT_EQ(phi(pairB), -0.01);
  EXPECT_EQ(phi(edge), -0.01);
}

// A neighbour not known here (a NaN ghost) leaves the node alone.
TEST(IsolatedNodes, AnUnknownNeighbourLeavesTheNodeAlone)
{
  double merged = 0.0;
  const auto opposite = [](int, int) { return 1.0; };
  EXPECT_TRUE(sltk::isolatedNodeValue<3>(-0.2, opposite, merged));
  EXPECT_EQ(merged, 1.0);
  const auto unknown = [](int a, int side) { return a == 2 && side > 0 ? std::nan("") : 1.0; };
  EXPECT_FALSE(sltk::isolatedNodeValue<3>(-0.2, unknown, merged));
  const auto sameSide = [](int a, int) { return a == 1 ? -0.1 : 1.0; };
  EXPECT_FALSE(sltk::isolatedNodeValue<3>(-0.2, sameSide, merged));
}
