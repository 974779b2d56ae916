// SPDX-License-Identifier: BSD-3-Clause
// The cloud's noise at its sampling scale (CloudNoise.h) and the automatic
// interpolator it chooses (AutomaticParameters.h, ReconstructionPlan.h).
#include "sltk/cloud/CloudNoise.h"
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/recon/AutomaticParameters.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <gtest/gtest.h>

#include <string>

namespace
{
template <int D>
double noiseOf(const sltk::PointCloud<D>& cloud, double& spacing)
{
  const sltk::PointLocator<D> locator(cloud);
  EXPECT_TRUE(sltk::cloudSpacing(locator, {}, spacing).isOk());
  double noise = -1.0;
  EXPECT_TRUE(sltk::cloudNoise(locator, spacing, {}, noise).isOk());
  return noise;
}
} // namespace

TEST(CloudNoise, ASmoothSampledSurfaceIsQuietAndGaussianNoiseIsMeasured)
{
  double spacing = 0.0;
  const sltk::PointCloud<3> clean = sltk::sphereCloud(20000);
  EXPECT_LT(noiseOf(clean, spacing), 0.01) << "a quadric through 12 neighbours fits a sphere to well below h_P";
  // Noise of 0.25 h_P along every axis: the residual of the fit estimates the
  // scatter along the normal (a little less: the fit absorbs some of it).
  const double sigma = 0.25 * spacing;
  double noisySpacing = 0.0;
  const double noisy = noiseOf(sltk::withGaussianNoise(clean, sigma, 7), noisySpacing);
  EXPECT_GT(noisy * noisySpacing, 0.6 * sigma);
  EXPECT_LT(noisy * noisySpacing, 1.3 * sigma);
}

TEST(CloudNoise, CurvesIn2D)
{
  double spacing = 0.0;
  const sltk::PointCloud<2> circle = sltk::circleCloud(4000);
  EXPECT_LT(noiseOf(circle, spacing), 0.01);
  double noisySpacing = 0.0;
  const double noisy = noiseOf(sltk::withGaussianNoise(circle, 0.25 * spacing, 3), noisySpacing);
  EXPECT_GT(noisy * noisySpacing, 0.6 * 0.25 * spacing);
}

TEST(CloudNoise, TooFewPointsAreRefused)
{
  const sltk::PointCloud<3> few = sltk::sphereCloud(sltk::NoiseNeighbours);
  const sltk::PointLocator<3> locator(few);
  double noise = 0.0;
  EXPECT_FALSE(sltk::cloudNoise(locator, 1.0, {}, noise).isOk());
}

TEST(CloudNoise, TheAutomaticInterpolatorFollowsTheNoise)
{
  sltk::ReconstructionOptions options;
  EXPECT_FALSE(options.Interpolator) << "automatic is the default";
  options.Guess = sltk::InitialGuess::BoundingSphere; // no K_P search: the plan in a fraction of a second
  sltk::ReconstructionPlan<3> clean, noisy, given;
  const sltk::PointCloud<3> sphere = sltk::sphereCloud(4000);
  ASSERT_TRUE(sltk::planReconstruction(sphere, options, {}, clean).isOk());
  EXPECT_EQ(clean.Options.Interpolator, sltk::InterpolatorKind::LeastSquaresQ1);
  EXPECT_GE(clean.CloudNoise, 0.0);
  EXPECT_LT(clean.CloudNoise, sltk::AutomaticInterpolatorNoise);
  bool logged = false;
  for (const std::string& choice : clean.Choices)
  {
    logged = logged || choice.rfind("interpolator lsq-q1: the cloud's noise is ", 0) == 0;
  }
  EXPECT_TRUE(logged) << "the choice and its reason are logged";

  ASSERT_TRUE(
    sltk::planReconstruction(sltk::withGaussianNoise(sphere, 0.3 * clean.userCloudSpacing(), 5), options, {}, noisy)
      .isOk());
  EXPECT_EQ(noisy.Options.Interpolator, sltk::InterpolatorKind::Weno3);
  EXPECT_GE(noisy.CloudNoise, sltk::AutomaticInterpolatorNoise);

  options.Interpolator = sltk::InterpolatorKind::Cweno; // given: used as given, no noise measured
  ASSERT_TRUE(sltk::planReconstruction(sphere, options, {}, given).isOk());
  EXPECT_EQ(given.Options.Interpolator, sltk::InterpolatorKind::Cweno);
  EXPECT_LT(given.CloudNoise, 0.0);
  EXPECT_EQ(sltk::ReconstructionOptions::thesis().Interpolator, sltk::InterpolatorKind::Weno3);
}
