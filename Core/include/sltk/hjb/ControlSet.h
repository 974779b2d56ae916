// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ControlSet.h
/// The compact control set A of the optimal control problem (3.1)-(3.4), in a
/// form a minimiser can use (thesis 3.2): membership, projection onto A, a
/// coarse tabulation grid of A, and a parametrisation for the local search.
///
/// Kinds:
///  - None:   no control (A = {} in 3.5.1: pure transport, no minimisation);
///  - Box:    prod_j [Lower_j, Upper_j] in R^M (Tests 2, 3);
///  - Ball:   |a - Center| <= Radius (Test 4: a disc);
///  - Sphere: |a - Center| = Radius (Test 5, Zermelo: unit speed, any heading);
///  - Finite: an explicit list of controls (tabulation only).
///
/// Local-search parameters p: Box and Ball use a itself (p = a, projected onto
/// A by clamping / radial scaling); a circle (Sphere, M = 2) uses the angle
/// theta, a = Center + Radius (cos theta, sin theta), so that every p is
/// admissible; a sphere in R^3 uses a in R^3 projected radially onto it.

#include "sltk/core/Index.h"
#include "sltk/core/Status.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace sltk
{

enum class ControlKind : std::uint8_t
{
  None = 0,
  Box = 1,
  Ball = 2,
  Sphere = 3,
  Finite = 4
};

/// Parameters of the local search over a control set of `kind` in R^m (0: tabulation only):
/// a box or a ball has m, a circle one angle, a 3D sphere its m coordinates (projected).
inline int controlParameterCount(ControlKind kind, int m)
{
  switch (kind)
  {
    case ControlKind::Box:
    case ControlKind::Ball:
      return m;
    case ControlKind::Sphere:
      return m == 2 ? 1 : m;
    default:
      return 0;
  }
}

template <int M>
struct ControlSet
{
  static_assert(M >= 1 && M <= 3, "controls live in R^1, R^2 or R^3");
  static constexpr int Dim = M;
  using Control = std::array<double, M>;

  ControlKind Kind = ControlKind::None;
  Control Lower{};             ///< Box: lower corner
  Control Upper{};             ///< Box: upper corner
  Control Center{};            ///< Ball, Sphere
  double Radius = 0.0;         ///< Ball, Sphere
  std::vector<Control> Points; ///< Finite

  static ControlSet none() { return ControlSet{}; }
  static ControlSet box(const Control& lower, const Control& upper)
  {
    ControlSet s;
    s.Kind = ControlKind::Box;
    s.Lower = lower;
    s.Upper = upper;
    return s;
  }
  static ControlSet ball(const Control& center, double radius)
  {
    ControlSet s;
    s.Kind = ControlKind::Ball;
    s.Center = center;
    s.Radius = radius;
    return s;
  }
  static ControlSet sphere(const Control& center, double radius)
  {
    ControlSet s;
    s.Kind = ControlKind::Sphere;
    s.Center = center;
    s.Radius = radius;
    return s;
  }
  static ControlSet finite(std::vector<Control> points)
  {
    ControlSet s;
    s.Kind = ControlKind::Finite;
    s.Points = std::move(points);
    return s;
  }

  bool empty() const { return this->Kind == ControlKind::None; }

  Status validate() const
  {
    switch (this->Kind)
    {
      case ControlKind::None:
        return Status::ok();
      case ControlKind::Box:
        for (int j = 0; j < M; ++j)
        {
          if (!(this->Upper[j] >= this->Lower[j]) || !std::isfinite(this->Lower[j]) || !std::isfinite(this->Upper[j]))
          {
            return Status::invalidArgument("control box axis " + std::to_string(j) + " is [" +
              std::to_string(this->Lower[j]) + ", " + std::to_string(this->Upper[j]) +
              "]: bounds must be finite with lower <= upper");
          }
        }
        return Status::ok();
      case ControlKind::Ball:
      case ControlKind::Sphere:
        if (!(this->Radius > 0.0) || !std::isfinite(this->Radius))
        {
          return Status::invalidArgument(
            "control ball/sphere radius must be positive and finite, got " + std::to_string(this->Radius));
        }
        if (this->Kind == ControlKind::Sphere && M == 1)
        {
          return Status::invalidArgument("a sphere in R^1 is two points: use ControlSet::finite");
        }
        return Status::ok();
      case ControlKind::Finite:
        if (this->Points.empty())
        {
          return Status::invalidArgument("a finite control set needs at least one control");
        }
        return Status::ok();
    }
    return Status::invalidArgument("unknown control set kind");
  }

  /// a in A up to tol (absolute).
  bool contains(const Control& a, double tol = 1e-12) const
  {
    switch (this->Kind)
    {
      case ControlKind::None:
        return false;
      case ControlKind::Box:
        for (int j = 0; j < M; ++j)
        {
          if (a[j] < this->Lower[j] - tol || a[j] > this->Upper[j] + tol)
          {
            return false;
          }
        }
        return true;
      case ControlKind::Ball:
        return this->distanceToCenter(a) <= this->Radius + tol;
      case ControlKind::Sphere:
        return std::fabs(this->distanceToCenter(a) - this->Radius) <= tol;
      case ControlKind::Finite:
        for (const Control& p : this->Points)
        {
          if (squaredDistance(a, p) <= tol * tol)
          {
            return true;
          }
        }
        return false;
    }
    return false;
  }

  /// Nearest point of A (Box: clamp; Ball/Sphere: radial; Finite: nearest
  /// point; None: a unchanged). The centre of a sphere goes to Center + Radius e_1.
  Control project(const Control& a) const
  {
    Control p = a;
    switch (this->Kind)
    {
      case ControlKind::None:
        break;
      case ControlKind::Box:
        for (int j = 0; j < M; ++j)
        {
          p[j] = a[j] < this->Lower[j] ? this->Lower[j] : (a[j] > this->Upper[j] ? this->Upper[j] : a[j]);
        }
        break;
      case ControlKind::Ball:
      case ControlKind::Sphere:
      {
        const double r = this->distanceToCenter(a);
        if (this->Kind == ControlKind::Ball && r <= this->Radius)
        {
          break;
        }
        if (!(r > 0.0))
        {
          p = this->Center;
          p[0] += this->Radius;
          break;
        }
        const double s = this->Radius / r;
        for (int j = 0; j < M; ++j)
        {
          p[j] = this->Center[j] + s * (a[j] - this->Center[j]);
        }
        break;
      }
      case ControlKind::Finite:
      {
        double best = std::numeric_limits<double>::infinity();
        for (const Control& q : this->Points)
        {
          const double d = squaredDistance(a, q);
          if (d < best)
          {
            best = d;
            p = q;
          }
        }
        break;
      }
    }
    return p;
  }

  /// Number of parameters of the local search (0: tabulation only).
  int parameterCount() const { return controlParameterCount(this->Kind, M); }

  /// True when parameter j is an angle (periodic, unbounded).
  bool isAngle() const { return this->Kind == ControlKind::Sphere && M == 2; }

  /// Makes parameters admissible in place (Box clamp, Ball/Sphere-in-R^3
  /// radial projection; angles need none).
  void projectParameters(double* p) const
  {
    if (this->isAngle() || this->parameterCount() == 0)
    {
      return;
    }
    Control a;
    for (int j = 0; j < M; ++j)
    {
      a[j] = p[j];
    }
    a = this->project(a);
    for (int j = 0; j < M; ++j)
    {
      p[j] = a[j];
    }
  }

  /// The control of admissible parameters p.
  Control fromParameters(const double* p) const
  {
    Control a{};
    if (this->isAngle())
    {
      a[0] = this->Center[0] + this->Radius * std::cos(p[0]);
      a[1] = this->Center[1] + this->Radius * std::sin(p[0]);
      return a;
    }
    for (int j = 0; j < M; ++j)
    {
      a[j] = p[j];
    }
    return a;
  }

  /// Parameters of a control of A (inverse of fromParameters()).
  void toParameters(const Control& a, double* p) const
  {
    if (this->isAngle())
    {
      p[0] = std::atan2(a[1] - this->Center[1], a[0] - this->Center[0]);
      return;
    }
    for (int j = 0; j < M; ++j)
    {
      p[j] = a[j];
    }
  }

  /// Bounds of parameter j for a 1D search (+-infinity for an angle or a sphere coordinate).
  void parameterBounds(int j, double& lo, double& hi) const
  {
    lo = -std::numeric_limits<double>::infinity();
    hi = std::numeric_limits<double>::infinity();
    if (this->Kind == ControlKind::Box)
    {
      lo = this->Lower[j];
      hi = this->Upper[j];
    }
    else if (this->Kind == ControlKind::Ball)
    {
      lo = this->Center[j] - this->Radius;
      hi = this->Center[j] + this->Radius;
    }
  }

  /// The coarse grid of A used for tabulation (thesis 3.2), first axis fastest
  /// (measured on Test 4: with an 8-cell cache this row order rebuilds fewer
  /// cells per node than a Z-order, 32 vs 41): Box: n points per
  /// axis including the corners (n^M); Ball: the n^M grid of its bounding box
  /// restricted to the ball (n odd contains the centre); circle: n equally
  /// spaced angles; sphere in R^3: the bounding-box grid projected radially
  /// (duplicates removed only at the centre); Finite: its points; None: none.
  std::vector<Control> tabulation(int n) const
  {
    std::vector<Control> out;
    n = n < 1 ? 1 : n;
    if (this->Kind == ControlKind::Finite)
    {
      return this->Points;
    }
    if (this->Kind == ControlKind::None)
    {
      return out;
    }
    if (this->isAngle())
    {
      const double twoPi = 6.283185307179586;
      for (int k = 0; k < n; ++k)
      {
        double theta[M] = {};
        theta[0] = twoPi * static_cast<double>(k) / static_cast<double>(n);
        out.push_back(this->fromParameters(theta));
      }
      return out;
    }
    Control lo{}, hi{};
    for (int j = 0; j < M; ++j)
    {
      this->parameterBounds(j, lo[j], hi[j]);
      if (this->Kind == ControlKind::Sphere)
      {
        lo[j] = this->Center[j] - this->Radius;
        hi[j] = this->Center[j] + this->Radius;
      }
    }
    Index total = 1;
    for (int j = 0; j < M; ++j)
    {
      total *= n;
    }
    for (Index k = 0; k < total; ++k)
    {
      Control a{};
      Index rest = k;
      for (int j = 0; j < M; ++j)
      {
        const Index i = rest % n;
        rest /= n;
        a[j] = n == 1 ? 0.5 * (lo[j] + hi[j])
                      : lo[j] + (hi[j] - lo[j]) * static_cast<double>(i) / static_cast<double>(n - 1);
      }
      if (this->Kind == ControlKind::Ball && !this->contains(a, 1e-12 * this->Radius))
      {
        continue;
      }
      if (this->Kind == ControlKind::Sphere)
      {
        if (!(this->distanceToCenter(a) > 1e-12 * this->Radius))
        {
          continue;
        }
        a = this->project(a);
      }
      out.push_back(a);
    }
    return out;
  }

  /// Spacing of tabulation(n) in parameter units: the initial step of the local search.
  double tabulationSpacing(int n) const
  {
    n = n < 2 ? 2 : n;
    if (this->isAngle())
    {
      return 6.283185307179586 / static_cast<double>(n);
    }
    double h = 0.0;
    for (int j = 0; j < M; ++j)
    {
      double lo = 0.0, hi = 0.0;
      this->parameterBounds(j, lo, hi);
      if (this->Kind == ControlKind::Sphere)
      {
        lo = this->Center[j] - this->Radius;
        hi = this->Center[j] + this->Radius;
      }
      const double s = (hi - lo) / static_cast<double>(n - 1);
      h = s > h ? s : h;
    }
    return h;
  }

private:
  double distanceToCenter(const Control& a) const { return std::sqrt(squaredDistance(a, this->Center)); }
  static double squaredDistance(const Control& a, const Control& b)
  {
    double s = 0.0;
    for (int j = 0; j < M; ++j)
    {
      s += (a[j] - b[j]) * (a[j] - b[j]);
    }
    return s;
  }
};

} // namespace sltk
