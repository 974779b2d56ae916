// SPDX-License-Identifier: BSD-3-Clause
// The options object every front end fills (the filters' properties, the CLI's flags):
// its ranges, FinalEta, and the typed summary the front ends read back.
#include "sltk/recon/ReconstructionOptions.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/recon/ReconstructionPlan.h"
#include "sltk/recon/ReconstructionSummary.h"

#include <gtest/gtest.h>

#include <string>

namespace
{
/// The message of validateOptionRanges for options changed by `change`.
template <class Change>
std::string refusal(Change change)
{
  sltk::ReconstructionOptions options;
  change(options);
  const sltk::Status status = sltk::validateOptionRanges(options);
  return status.isOk() ? std::string() : status.message();
}

bool mentions(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
} // namespace

TEST(OptionRanges, DefaultsAndThesisAreInRange)
{
  EXPECT_TRUE(sltk::validateOptionRanges(sltk::ReconstructionOptions{}).isOk());
  EXPECT_TRUE(sltk::validateOptionRanges(sltk::ReconstructionOptions::thesis()).isOk());
}

TEST(OptionRanges, RefusalNamesThePropertyAndItsRange)
{
  // The filters report these messages as they are: each names the property and Core's range.
  EXPECT_TRUE(mentions(refusal([](auto& o) { o.Padding = 2; }), "Padding = 2 is outside its range [4, 1000]"));
  EXPECT_TRUE(mentions(refusal([](auto& o) { o.Runs = 7; }), "NumberOfRuns = 7"));
  EXPECT_TRUE(mentions(refusal([](auto& o) { o.CellSizeFactor = 0.01; }), "or 0 for automatic"));
  EXPECT_TRUE(mentions(refusal([](auto& o) { o.FinalEta = -1.0; }), "FinalEta = -1"));
  EXPECT_TRUE(mentions(refusal([](auto& o) { o.Cleaning.ThinningFactor = 101.0; }), "ThinningFactor = 101"));
  EXPECT_TRUE(mentions(refusal([](auto& o) { o.MemoryBudget = 5u << 20; }), "MemoryBudget = 5 is outside"))
    << "the budget is named in MB, as the front ends give it";
  EXPECT_TRUE(refusal([](auto& o) { o.MemoryBudget = 16u << 20; }).empty());
  EXPECT_TRUE(mentions(refusal([](auto& o) { o.Guess = static_cast<sltk::InitialGuess>(3); }), "InitialGuess = 3"));
  EXPECT_TRUE(mentions(
    refusal([](auto& o) { o.Interpolator = static_cast<sltk::InterpolatorKind>(9); }), "Interpolator 9 is not"));
  EXPECT_TRUE(mentions(refusal([](auto& o) { o.Schedule = { { 0.5, 1.0 } }; }), "run schedule pair 1"));
}

TEST(OptionRanges, FinalEtaIsTable41WithTheLastRunsEta)
{
  sltk::ReconstructionOptions options;
  options.FinalEta = 3.0;
  for (int run = 1; run <= 5; ++run)
  {
    const sltk::RunParameters got = options.parameters(run), table = sltk::table41(run);
    EXPECT_EQ(got.P, table.P) << run;
    EXPECT_EQ(got.Eta, run >= 3 ? 3.0 : table.Eta) << run;
  }
  options.Schedule = { { 1.0, 0.0 }, { 2.0, 0.5 } }; // a schedule replaces FinalEta
  EXPECT_EQ(options.parameters(4).Eta, 0.5);
}

TEST(OptionRanges, SummaryHoldsTheResultsRecords)
{
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.Runs = 2;
  sltk::ReconstructionResult<2> result;
  ASSERT_TRUE(sltk::reconstruct(sltk::circleCloud(64), options, sltk::Context{}, result).isOk());
  const sltk::ReconstructionSummary summary = sltk::summarize(result);
  EXPECT_EQ(summary.CloudSpacing, result.CloudSpacing);
  EXPECT_EQ(summary.CellSizeFactor, result.CellSizeFactor);
  EXPECT_EQ(summary.OutsideThresholdFactor, result.OutsideThresholdFactor);
  EXPECT_EQ(summary.Cleaning.OutputPoints, result.Cleaning.OutputPoints);
  EXPECT_EQ(summary.Choices, result.Choices);
  EXPECT_FALSE(summary.OctreeStorage);
  ASSERT_EQ(summary.Runs.size(), result.Runs.size());
  for (size_t r = 0; r < summary.Runs.size(); ++r)
  {
    const sltk::RunSummary& run = summary.Runs[r];
    EXPECT_EQ(run.GridDimensions[0], result.Runs[r].Grid.Dims[0]);
    EXPECT_EQ(run.GridDimensions[1], result.Runs[r].Grid.Dims[1]);
    EXPECT_EQ(run.GridDimensions[2], 1) << "a 2D run has one node along z";
    EXPECT_EQ(run.Iterations, result.Runs[r].Iterations);
    EXPECT_EQ(run.CloudError, result.Runs[r].CloudError);
    EXPECT_EQ(run.Energy, result.Runs[r].Energy);
  }
}
