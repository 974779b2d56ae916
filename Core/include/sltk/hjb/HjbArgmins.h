// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbArgmins.h
/// The argmin of (3.7) at every node after the last step, in the minimiser's
/// parameters: the warm start of the next step's minimisation when
/// MinimizerOptions::WarmTabulationPoints > 0 (ControlMinimizer::minimizeFrom).
/// n x q doubles (q local-search parameters), NaN until a node has one.

#include "sltk/grid/GridSpec.h"

#include <cmath>
#include <limits>
#include <vector>

namespace sltk
{

class HjbArgmins
{
public:
  /// Forgets every argmin; `count` parameters per node.
  void reset(Index nodes, int count)
  {
    this->Count = count;
    this->Values.assign(
      static_cast<size_t>(nodes) * static_cast<size_t>(count), std::numeric_limits<double>::quiet_NaN());
  }

  /// Parameters per node (0: nothing stored).
  int count() const { return this->Count; }
  /// Number of nodes held.
  Index nodes() const { return this->Count > 0 ? static_cast<Index>(this->Values.size()) / this->Count : 0; }

  /// True when node k has an argmin from a previous step.
  bool has(Index k) const { return this->Count > 0 && !std::isnan(this->Values[this->offset(k)]); }
  const double* at(Index k) const { return this->Values.data() + this->offset(k); }
  double* at(Index k) { return this->Values.data() + this->offset(k); }

private:
  size_t offset(Index k) const { return static_cast<size_t>(k) * static_cast<size_t>(this->Count); }

  int Count = 0;
  std::vector<double> Values;
};

} // namespace sltk
