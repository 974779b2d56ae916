// SPDX-License-Identifier: BSD-3-Clause
// Tunnel detection (thesis 4.5.6): a square outline with a long narrow slot
// (two close parallel lines of points, Fig. 4.19). From the outside-marking
// initial surface the front is stopped at the slot's mouth, where grad phi and
// grad d become orthogonal, and plugs it; following grad phi where d < 2 dx and
// |grad d| < 0.5 lets it go down the slot.
#include "sltk/recon/Reconstruction.h"

#include "sltk/cloud/SyntheticClouds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace
{
/// The square [-1, 1]^2 with a slot of width 2w from the top edge down to y = bottom.
sltk::PointCloud<2> slottedSquare(double w, double bottom, double h)
{
  return sltk::polygonCloud({ { -1.0, -1.0 }, { 1.0, -1.0 }, { 1.0, 1.0 }, { w, 1.0 }, { w, bottom }, { -w, bottom },
                              { -w, 1.0 }, { -1.0, 1.0 } },
    h);
}

/// phi at the node nearest to (x, y).
double phiAt(const sltk::GridField<2>& phi, double x, double y)
{
  const auto& g = phi.spec();
  std::array<sltk::Index, 2> i{ static_cast<sltk::Index>(std::lround((x - g.Origin[0]) / g.Spacing[0])),
    static_cast<sltk::Index>(std::lround((y - g.Origin[1]) / g.Spacing[1])) };
  for (int a = 0; a < 2; ++a)
  {
    i[a] = std::clamp<sltk::Index>(i[a], 0, g.Dims[a] - 1);
  }
  return phi(i);
}

struct SlotRun
{
  double InSlot; ///< phi in the slot, at (0, 0.2)
  double CloudError;
};

SlotRun slotRun(double halfWidth, bool detect)
{
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  options.Runs = 2;
  options.DetectTunnels = detect;
  sltk::ReconstructionResult<2> result;
  const sltk::Status s = sltk::reconstruct(slottedSquare(halfWidth, -0.2, 0.02), options, sltk::Context{}, result);
  EXPECT_TRUE(s.isOk()) << s.message();
  const double inSlot = phiAt(result.SignedDistance, 0.0, 0.2);
  std::cout << "slot half-width " << halfWidth << (detect ? ", with" : ", without")
            << " tunnel detection: phi in the slot " << inSlot << ", Err_P " << result.Runs.back().CloudError << "\n";
  EXPECT_LT(phiAt(result.SignedDistance, -0.5, 0.0), 0.0) << "the square's body is inside";
  return { inSlot, result.Runs.back().CloudError };
}
} // namespace

TEST(TunnelDetection, NarrowSlotIsPluggedWithoutAndOpenedWith)
{
  // Slot 3 h_P wide. Measured: without, phi = -0.040 in the slot, Err_P 9.9e-3 (the slot's walls
  // are far from the plug); with, phi = +0.024, Err_P 7.5e-4.
  const SlotRun plugged = slotRun(0.03, false);
  EXPECT_LT(plugged.InSlot, 0.0) << "the known drawback: the front stops at the slot's mouth";
  EXPECT_GT(plugged.CloudError, 5e-3);
  const SlotRun opened = slotRun(0.03, true);
  EXPECT_GT(opened.InSlot, 0.0) << "4.5.6: the front goes down the slot";
  EXPECT_LT(opened.CloudError, 2e-3);
}

TEST(TunnelDetection, WideSlotIsUnharmed)
{
  // Slot 8 h_P wide, open anyway: Err_P 1.8e-4 without, 2.8e-4 with detection.
  const SlotRun without = slotRun(0.08, false);
  const SlotRun with = slotRun(0.08, true);
  EXPECT_GT(without.InSlot, 0.0);
  EXPECT_GT(with.InSlot, 0.0);
  EXPECT_LT(with.CloudError, 2.0 * without.CloudError);
}
