// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CutOff.h
/// Localisation thresholds and the cut-off function of the narrow-band level
/// set method (thesis 1.6, after Peng et al. [94]).

#include <cmath>

namespace sltk
{

/// beta < gamma of (1.56); the reconstruction uses beta = 2 dx, gamma = 4 dx (4.4.6).
struct BandWidths
{
  double Beta = 0.0;
  double Gamma = 0.0;

  static BandWidths forSpacing(double dx, double betaHat = 2.0, double gammaHat = 4.0)
  {
    return { betaHat * dx, gammaHat * dx };
  }
};

/// cut-off (1.55): 1 for |phi| <= beta, the cubic
/// (|phi| - gamma)^2 (2|phi| + gamma - 3 beta) / (gamma - beta)^3 for
/// beta < |phi| <= gamma, 0 beyond. C1: the cubic is 1 with zero slope at
/// beta and 0 with zero slope at gamma.
inline double cutOff(double phi, double beta, double gamma)
{
  const double a = std::fabs(phi);
  if (a <= beta)
  {
    return 1.0;
  }
  if (a > gamma)
  {
    return 0.0;
  }
  const double g = gamma - beta;
  return (a - gamma) * (a - gamma) * (2.0 * a + gamma - 3.0 * beta) / (g * g * g);
}

inline double cutOff(double phi, const BandWidths& w)
{
  return cutOff(phi, w.Beta, w.Gamma);
}

/// cutting (1.49): phi clamped to [-gamma, gamma].
inline double cutLevel(double phi, double gamma)
{
  return phi < -gamma ? -gamma : (phi > gamma ? gamma : phi);
}

} // namespace sltk
