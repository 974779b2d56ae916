// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SkewedSteps.h
/// The order in which several Jacobi pseudo-time steps of (1.30) visit a band
/// that is sorted by planes of the slowest axis, so that the steps share each
/// plane's trip through the caches (time skewing; Documentation/Profile.md,
/// "The pseudo-time steps in skewed waves").
///
/// A step of plane z reads the previous step's values on planes z - 1, z and
/// z + 1 (the 1 + 2D-point stencils (1.33) of (1.32)/(1.35)) and writes its own values
/// into a buffer; once step t of plane z is done, nothing reads step t - 1 of
/// plane z - 1 any more, and step t of plane z - 1 goes back into phi. Step t
/// of plane z runs in wave z + SkewLag t. With a lag of 3 planes a step, every
/// value a task reads was written back in an earlier wave and no task of a wave
/// reads or writes a plane another one writes, so the tasks of one wave run in
/// parallel and each node gets the values of the plain step after step, bit
/// for bit, on any number of threads. The same holds for groups of consecutive
/// planes in place of planes (a task steps its planes in order, each followed
/// by the write back of the one before): a group reads only the planes next to
/// it of the groups beside it, and with a lag of 3 groups the tasks of a wave
/// are at least one plane apart (a lag of 2 races when a group is one plane).

#include "sltk/core/Index.h"
#include "sltk/exec/Context.h"

#include <algorithm>
#include <cmath>

namespace sltk
{
namespace detail
{

/// Planes between the tasks of consecutive steps in one wave.
constexpr Index SkewLag = 3;
/// A round takes MinimumSkewedRound to MaximumSkewedRound steps; a task at
/// least SkewedTaskNodes nodes (a group of planes), so that a wave's threads
/// work more than they wait for each other.
constexpr int MinimumSkewedRound = 3;
constexpr int MaximumSkewedRound = 10;
constexpr Index SkewedTaskNodes = 1024;

/// The steps of the next skewed round, `left` at most: MaximumSkewedRound, or
/// once two steps are done (their largest changes `before`, `latest`) as many
/// as their ratio says the largest change needs to fall below `tolerance` (and
/// one more), since the steps beyond the tolerance stop are done in vain. A
/// round shorter than MinimumSkewedRound is one plain step.
inline int skewedRound(double before, double latest, int left, double tolerance)
{
  int round = MaximumSkewedRound;
  if (latest > 0.0 && latest < before) // a geometric fall: latest (latest / before)^n < tolerance
  {
    const double needed = std::log(tolerance / latest) / std::log(latest / before);
    round = needed < MaximumSkewedRound ? std::max(1, static_cast<int>(std::ceil(needed)) + 1) : MaximumSkewedRound;
  }
  round = std::min(round, left);
  return round < MinimumSkewedRound ? 1 : round;
}

/// Calls task(t, g) for every step t in [0, steps) and group of planes g in
/// [0, groups] in the skewed waves above; task(t, groups) has no plane to
/// step, only the write-back of the last plane. The tasks of a wave run in
/// parallel, the waves one after the other.
template <class Task>
void skewedWaves(Index groups, Index steps, const Context& ctx, Task&& task)
{
  const Index waves = groups + 1 + SkewLag * (steps - 1);
  for (Index w = 0; w < waves; ++w)
  {
    // The steps t of this wave: 0 <= w - SkewLag t <= groups.
    const Index first = w > groups ? (w - groups + SkewLag - 1) / SkewLag : 0;
    const Index last = std::min(steps - 1, w / SkewLag);
    ctx.parallelFor(
      first, last + 1,
      [&](Index b, Index e)
      {
        for (Index t = b; t < e; ++t)
        {
          task(t, w - SkewLag * t);
        }
      },
      1);
  }
}

} // namespace detail
} // namespace sltk
