// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/GridPlan.h"

#include "sltk/exec/Memory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

TEST(GridPlan, RunsHalveTheSpacing)
{
  sltk::Box<2> box{ { -1.0, -1.0 }, { 1.0, 1.0 } };
  sltk::GridPlanOptions opt;
  opt.Runs = 3;
  opt.CellSizeFactor = 1.0;
  opt.Padding = 10;
  sltk::GridPlan<2> plan;
  ASSERT_TRUE(sltk::planGrids(box, 0.1, opt, plan).isOk());
  ASSERT_EQ(plan.Runs.size(), 3u);
  EXPECT_DOUBLE_EQ(plan.Runs[0].Spacing[0], 0.1);   // (4.36), r = 1
  EXPECT_DOUBLE_EQ(plan.Runs[2].Spacing[1], 0.025); // r = 3
  EXPECT_EQ(plan.Runs[0].Dims[0], 20 + 1 + 20);
  EXPECT_EQ(plan.Runs[2].Dims[0], 80 + 1 + 20);
  // The cloud is centred and covered with the padding on both sides.
  const auto& g = plan.Runs[1];
  EXPECT_NEAR(g.Origin[0], -1.0 - 10 * 0.05, 1e-12);
  EXPECT_NEAR(g.coordinate(0, g.Dims[0] - 1), 1.0 + 10 * 0.05, 1e-12);
}

TEST(GridPlan, RefusesGridsBeyondTheMemoryBudgetWithASuggestion)
{
  sltk::Box<3> box{ { 0.0, 0.0, 0.0 }, { 1.0, 1.0, 1.0 } };
  sltk::GridPlanOptions opt;
  opt.Runs = 3;
  opt.MemoryBudget = 1000000000; // 1 GB
  sltk::GridPlan<3> plan;
  auto s = sltk::planGrids(box, 1e-3, opt, plan); // 4000^3 nodes in run 3
  EXPECT_EQ(s.code(), sltk::StatusCode::OutOfMemory);
  EXPECT_NE(s.message().find("use C_dx >="), std::string::npos) << s.message();
  EXPECT_TRUE(plan.Runs.empty());
  opt.CellSizeFactor = 30.0;
  EXPECT_TRUE(sltk::planGrids(box, 1e-3, opt, plan).isOk());
}

TEST(GridPlan, OctreeLevelsGiveTheFinestCell)
{
  // (5.1), (5.10)-(5.11): the finest cell is the cloud's extent / 2^L; run 1 is L - R + 1.
  const double extent = 3.0, hP = 0.01;
  for (int level = 4; level <= 12; ++level)
  {
    const double cdx = sltk::cellSizeFactorForLevel(level, 3, extent, hP);
    EXPECT_DOUBLE_EQ(cdx * hP / 4.0, extent / std::ldexp(1.0, level)) << level;
    EXPECT_EQ(sltk::levelForCellSizeFactor(cdx, 3, extent, hP), level) << "the level of its own C_dx";
    EXPECT_EQ(sltk::levelForCellSizeFactor(cdx * 1.01, 3, extent, hP), level - 1) << "a coarser C_dx: one level less";
  }
}

TEST(GridPlan, RejectsBadParameters)
{
  sltk::Box<2> box{ { 0.0, 0.0 }, { 1.0, 1.0 } };
  sltk::GridPlan<2> plan;
  EXPECT_FALSE(sltk::planGrids(box, 0.0, {}, plan).isOk());
  sltk::GridPlanOptions opt;
  opt.Runs = 0;
  EXPECT_FALSE(sltk::planGrids(box, 0.1, opt, plan).isOk());
}

TEST(Memory, ReadsProcOnLinux)
{
  EXPECT_GT(sltk::availableMemoryBytes(), 0u);
  EXPECT_GT(sltk::peakResidentBytes(), 0u);
}

TEST(GridPlan, AbsurdResolutionsDoNotOverflow)
{
  sltk::Box<3> box{ { 0.0, 0.0, 0.0 }, { 1.0, 1.0, 1.0 } };
  sltk::GridPlanOptions opt;
  opt.CellSizeFactor = 1e-12;
  sltk::GridPlan<3> plan;
  auto s = sltk::planGrids(box, 1e-3, opt, plan);
  EXPECT_EQ(s.code(), sltk::StatusCode::OutOfMemory);
  EXPECT_NE(s.message().find("1e9 nodes along axis"), std::string::npos) << s.message();
}
