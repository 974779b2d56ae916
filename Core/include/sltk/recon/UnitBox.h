// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file UnitBox.h
/// The thesis rescales every cloud into [-1, 1]^d (4.5): the model (4.9) is
/// not scale-invariant for p > 1 (d / E_p has the dimension of 1/length).
/// A UnitBox maps the user's coordinates to that box and back.

#include "sltk/cloud/PointCloud.h"
#include "sltk/grid/GridField.h"

#include <algorithm>
#include <array>

namespace sltk
{

template <int D>
struct UnitBox
{
  std::array<double, D> Centre{};
  double Scale = 1.0; ///< user length = Scale * unit-box length

  UnitBox() = default;
  explicit UnitBox(const Box<D>& box)
  {
    double half = 0.0;
    for (int a = 0; a < D; ++a)
    {
      this->Centre[a] = 0.5 * (box.Min[a] + box.Max[a]);
      half = std::max(half, 0.5 * box.extent(a));
    }
    this->Scale = half;
  }

  /// A position in the unit box.
  std::array<double, D> toUnit(std::array<double, D> p) const
  {
    for (int a = 0; a < D; ++a)
    {
      p[a] = (p[a] - this->Centre[a]) / this->Scale;
    }
    return p;
  }

  /// Moves the points of `cloud` into the unit box, in place.
  void toUnit(PointCloud<D>& cloud) const
  {
    for (auto& p : cloud.Points)
    {
      p = this->toUnit(p);
    }
  }

  /// A position back in the user's units.
  std::array<double, D> toUser(std::array<double, D> p) const
  {
    for (int a = 0; a < D; ++a)
    {
      p[a] = this->Centre[a] + this->Scale * p[a];
    }
    return p;
  }

  /// Moves the points of `cloud` back to the user's units, in place.
  void toUser(PointCloud<D>& cloud) const
  {
    for (auto& p : cloud.Points)
    {
      p = this->toUser(p);
    }
  }

  GridSpec<D> toUser(GridSpec<D> g) const
  {
    for (int a = 0; a < D; ++a)
    {
      g.Origin[a] = this->Centre[a] + this->Scale * g.Origin[a];
      g.Spacing[a] *= this->Scale;
    }
    return g;
  }

  /// Lengths (phi, d) and the grid back to the user's units.
  void toUser(GridField<D>& f) const
  {
    const GridSpec<D> g = this->toUser(f.spec());
    f.setGeometry(g.Origin, g.Spacing);
    for (double& v : f.storage())
    {
      v *= this->Scale;
    }
  }
};

} // namespace sltk
