// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReinitOptions.h
/// Parameters and outcome of the narrow-band reinitialisation (thesis 1.5).

#include "sltk/core/Status.h"
#include "sltk/grid/GridSpec.h"
#include "sltk/levelset/ReinitScheme.h"

#include <cmath>
#include <cstdint>
#include <string>

namespace sltk
{

/// How the nodes next to the front (the set X of (1.38)) are treated.
enum class ReinitMethod : std::uint8_t
{
  /// (1.30) with (1.31) on every band node, X included.
  Plain = 0,
  /// Russo-Smereka (1.36): nodes of X relax towards the distance (1.37),
  /// phi - dtau/dx (S(phi0) |phi| - d), the others follow (1.30).
  RussoSmereka = 1,
  /// Hartmann et al.'s constrained reinitialisation (1.38)-(1.45), the one the
  /// thesis uses for surface reconstruction (4.4.5): X is set once, explicitly,
  /// to (1.37) on R1 and (1.44) on R2 and kept fixed while (1.30) fills the band.
  Constrained = 2
};

struct ReinitOptions
{
  ReinitMethod Method = ReinitMethod::Constrained;
  ReinitScheme Scheme = ReinitScheme::Godunov; ///< (1.35); Upwind is (1.32)
  /// dtau = Courant * dx (smallest spacing), as (1.34): dtau / dx |s| <= 1/2.
  double Courant = 0.5;
  /// Pseudo-time steps at most; 0 applies only the explicit step on X.
  int MaxIterations = 50;
  /// Stop when the largest change of a step in the band is below Tolerance * dx.
  double Tolerance = 1e-4;

  /// Largest monotone Courant number in D dimensions: the step's weight on the
  /// node is 1 - Courant |s| sum_a |q_a| / |q| over the upwind differences q used,
  /// D of them for (1.35), up to 2D for (1.32), so 1/sqrt(D) and 1/sqrt(2D).
  /// (1.34)'s 1/2 is the 2D bound of (1.32); (1.32) in 3D needs <= 1/sqrt(6).
  template <int D>
  double courantLimit() const
  {
    const int terms = this->Scheme == ReinitScheme::Godunov ? D : 2 * D;
    return 1.0 / std::sqrt(static_cast<double>(terms));
  }

  /// Courant in (0, courantLimit()], MaxIterations >= 0, Tolerance >= 0.
  template <int D>
  Status validate() const
  {
    const double limit = this->courantLimit<D>();
    if (!(this->Courant > 0.0) || this->Courant > limit)
    {
      return Status::invalidArgument("reinitialisation Courant number " + std::to_string(this->Courant) +
        " is outside (0, " + std::to_string(limit) + "], the monotonicity bound of the " +
        (this->Scheme == ReinitScheme::Godunov ? "Godunov (1.35)" : "upwind (1.32)") + " scheme in " +
        std::to_string(D) + "D");
    }
    if (this->MaxIterations < 0)
    {
      return Status::invalidArgument("reinitialisation MaxIterations must be >= 0");
    }
    if (!(this->Tolerance >= 0.0))
    {
      return Status::invalidArgument("reinitialisation Tolerance must be >= 0");
    }
    return Status::ok();
  }
};

struct ReinitReport
{
  int Iterations = 0;       ///< pseudo-time steps done
  double MaxChange = 0.0;   ///< largest |change| of a band value in the last step
  bool Converged = false;   ///< MaxChange < Tolerance * dx was reached
  Index InterfaceNodes = 0; ///< band nodes in the set X of (1.38)
};

} // namespace sltk
