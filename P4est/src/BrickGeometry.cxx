// SPDX-License-Identifier: GPL-2.0-or-later
#include "sltk/p4est/BrickGeometry.h"

#include <algorithm>
#include <limits>

namespace sltk
{
namespace p4est
{

namespace
{
/// Trees needed along an extent; the small tolerance keeps an extent that is
/// a whole number of trees from getting one more tree through rounding.
int treesAlong(double extent, double edge)
{
  return std::max(1, static_cast<int>(std::ceil(extent / edge * (1.0 - 1e-12))));
}
} // namespace

BrickGeometry brickOver(const Box<3>& box, double padding)
{
  double largest = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    largest = std::max(largest, box.extent(a));
  }
  const double pad = padding * largest;
  std::array<double, 3> extent{};
  double smallest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
  {
    extent[a] = box.extent(a) + 2.0 * pad;
    smallest = std::min(smallest, extent[a]);
  }
  // Candidate edges: an extent split into n trees, no shorter than the
  // smallest extent (one tree across the thinnest axis) nor than
  // 1/MaxTreesPerAxis of the largest; the brick of least volume wins (then
  // the one with fewer trees).
  const double shortest = std::max(smallest, (largest + 2.0 * pad) / MaxTreesPerAxis) * (1.0 - 1e-12);
  BrickGeometry brick;
  double bestVolume = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
  {
    for (int n = 1; n <= MaxTreesPerAxis; ++n)
    {
      const double edge = extent[a] / n;
      std::array<int, 3> trees{};
      bool fits = edge > 0.0 && edge >= shortest;
      for (int b = 0; b < 3 && fits; ++b)
      {
        trees[b] = treesAlong(extent[b], edge);
        fits = trees[b] <= MaxTreesPerAxis;
      }
      const double volume = fits ? trees[0] * trees[1] * trees[2] * edge * edge * edge : bestVolume;
      if (volume < bestVolume * (1.0 - 1e-9) || (volume <= bestVolume * (1.0 + 1e-9) && edge > brick.TreeEdge))
      {
        bestVolume = volume;
        brick.TreeEdge = edge;
        brick.Trees = trees;
      }
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    const double centre = 0.5 * (box.Min[a] + box.Max[a]);
    brick.Origin[a] = centre - 0.5 * brick.Trees[a] * brick.TreeEdge;
  }
  return brick;
}

} // namespace p4est
} // namespace sltk
