// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/octree/TiledReinitStep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace
{
using sltk::Index;
using Step = sltk::TiledReinitStep<3>;

/// A field of 3 x 3 x 2 slots over a grid that ends inside the last ones:
/// tiles in most slots, one slot inside, one Remote, the rest outside; the
/// values random, with NaN, infinities and signed zeros among them if `special`.
sltk::TiledField<3> randomField(std::mt19937& random, bool special = true)
{
  sltk::GridSpec<3> grid;
  grid.Dims = { 22, 24, 13 };
  grid.Spacing = { 0.5, 0.25, 0.4 };
  grid.Origin = { 0.0, 0.0, 0.0 };
  sltk::TiledField<3> field;
  field.reset(grid, 0.75);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const double odd[] = { std::numeric_limits<double>::quiet_NaN(), HUGE_VAL, -HUGE_VAL, 0.0, -0.0 };
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    if (s == 4)
    {
      field.setSide(s, true);
      continue;
    }
    if (s == 7)
    {
      field.setRemote(s);
      continue;
    }
    if (s % 5 == 3)
    {
      continue; // outside
    }
    const std::int32_t id = field.addTile(s);
    for (Index k = 0; k < sltk::TiledField<3>::Nodes; ++k)
    {
      field.phi(id)[k] = special && random() % 200 == 0 ? odd[random() % 5] : value(random);
    }
  }
  return field;
}

/// Every node of every tile but a few, tile after tile, with random roles and coefficients.
struct RandomBand
{
  std::vector<Step::Node> Nodes;
  std::vector<double> Coefficient;
  std::vector<std::uint8_t> Fixed, Relax;

  RandomBand(const sltk::TiledField<3>& field, std::mt19937& random)
  {
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (std::int32_t id = 0; id < field.tileCount(); ++id)
    {
      for (Index k = 0; k < sltk::TiledField<3>::Nodes; ++k)
      {
        if (random() % 7 == 0)
        {
          continue;
        }
        this->Nodes.push_back({ id, static_cast<std::int32_t>(k) });
        this->Coefficient.push_back(random() % 50 == 0 ? 0.0 : value(random));
        this->Fixed.push_back(random() % 10 == 0 ? 1 : 0);
        this->Relax.push_back(random() % 5 == 0 ? 1 : 0);
      }
    }
  }

  Step::Band band() const
  {
    return { this->Nodes.data(), this->Coefficient.data(), this->Fixed.data(), this->Relax.data() };
  }
};

/// Runs step() (AVX2 where the processor has it) and stepPairs() against
/// stepNodes() on `band`; returns the number of differing results.
int stepMismatches(const Step& step, const RandomBand& band)
{
  const Index count = static_cast<Index>(band.Nodes.size());
  int mismatches = 0;
  for (const sltk::ReinitMethod method : { sltk::ReinitMethod::Constrained, sltk::ReinitMethod::RussoSmereka })
  {
    for (const sltk::ReinitScheme scheme : { sltk::ReinitScheme::Godunov, sltk::ReinitScheme::Upwind })
    {
      sltk::ReinitOptions options;
      options.Method = method;
      options.Scheme = scheme;
      for (Index b : { Index(0), Index(1), Index(3) })
      {
        for (Index e : { count, count - 2, b + 2049 })
        {
          std::vector<double> nodes(band.Nodes.size(), -7.0), lanes = nodes, pairs = nodes;
          double largest = 0.0;
          step.stepNodes(band.band(), options, 0.1, b, e, nodes.data(), largest);
          const double inLanes = step.step(band.band(), options, 0.1, b, e, lanes.data());
          const double inPairs = step.stepPairs(band.band(), options, 0.1, b, e, pairs.data());
          const size_t bytes = nodes.size() * sizeof(double);
          mismatches += std::memcmp(nodes.data(), lanes.data(), bytes) != 0;
          mismatches += std::memcmp(nodes.data(), pairs.data(), bytes) != 0;
          mismatches += std::memcmp(&largest, &inLanes, sizeof(double)) != 0;
          mismatches += std::memcmp(&largest, &inPairs, sizeof(double)) != 0;
        }
      }
    }
  }
  return mismatches;
}
} // namespace

TEST(TiledReinitStep, AxesAreTheFieldsValues)
{
  // Across a tile face the neighbour is the next tile's node, a slot's +-gamma or NaN, and beyond
  // the grid's first node +gamma (TiledField::value, as the classification's copies read it)
  // or the node's own value (the pseudo-time steps' constant extension).
  std::mt19937 random(7);
  sltk::TiledField<3> field = randomField(random);
  for (const Step::Lower lower : { Step::Lower::Gamma, Step::Lower::Self })
  {
    Step step;
    step.prepare(field, lower);
    for (std::int32_t id = 0; id < field.tileCount(); ++id)
    {
      for (Index k = 0; k < sltk::TiledField<3>::Nodes; ++k)
      {
        double u[7];
        step.axes({ id, static_cast<std::int32_t>(k) }, u);
        const auto i = field.node(id, k);
        for (int e = 0; e < 7; ++e)
        {
          auto j = i;
          j[static_cast<size_t>(std::max(0, (e - 1) / 2))] += e == 0 ? 0 : (e % 2 ? -1 : 1);
          const bool self = lower == Step::Lower::Self && e % 2 == 1 && j[static_cast<size_t>((e - 1) / 2)] < 0;
          const double expected = self ? u[0] : field.value(j);
          ASSERT_EQ(std::memcmp(&u[e], &expected, sizeof(double)), 0) << "tile " << id << " node " << k << " " << e;
        }
      }
    }
  }
}

TEST(TiledReinitStep, LanesAreTheNodeByNodeStepBitForBit)
{
  // Four (AVX2) or two lanes against the scalar step of every node: the values written and the
  // largest change (HUGE_VAL with a value not finite), for both schemes, with and without (1.36),
  // the nodes started anywhere (groups across tiles, a remainder).
  for (const bool special : { false, true })
  {
    std::mt19937 random(11);
    sltk::TiledField<3> field = randomField(random, special);
    const RandomBand band(field, random);
    Step step;
    step.setSpacing(field.grid());
    step.prepare(field, Step::Lower::Self);
    EXPECT_EQ(stepMismatches(step, band), 0) << (special ? "with" : "without") << " special values";
  }
}
