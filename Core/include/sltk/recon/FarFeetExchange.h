// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file FarFeetExchange.h
/// The feet of one SL step that lie beyond a rank's window (FarFeet,
/// LevelSetStep.h), interpolated by the ranks that own their rows: one batched
/// exchange per step, never a message per foot (thesis 4.4.1). Every rank
/// gathers every rank's far feet (few: the band nodes whose scale factor
/// (4.32) is large, where the band spans a gap of the cloud), interpolates
/// those whose row it owns on its phi^n, and the answers are gathered back in
/// the same order. A foot's owner has the foot's whole stencil in its window
/// (the ghost rows exceed the stencil), so the value is the one-rank value.
/// Two collective calls; one when no rank has a far foot.

#include "sltk/exec/Communicator.h"
#include "sltk/grid/Slabs.h"
#include "sltk/interp/CellCache.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/recon/SlabPolicy.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace sltk
{

/// Fills the far feet's values (far.Values) of every rank; `phi` is this
/// rank's window of phi^n (rows of `whole` cut at `boundaries`, every rank's
/// first row and the row count) with its ghost layers filled
/// (levelSetStepValues() did). Returns the number of far feet over all ranks
/// through `total`. A collective call.
template <class Interp, int D>
Status resolveFarFeet(const GridField<D>& phi, FarFeet<D>& far, const GridSpec<D>& whole,
  const std::vector<Index>& boundaries, const Communicator& comm, double& total)
{
  const int size = comm.size(), rank = comm.rank();
  std::vector<unsigned char> allFeet;
  std::vector<std::int64_t> counts;
  comm.allGatherV(far.Feet.data(), far.Feet.size() * sizeof(std::array<double, D>), allFeet, counts);
  const size_t footBytes = sizeof(std::array<double, D>);
  const size_t feet = allFeet.size() / footBytes;
  total = static_cast<double>(feet);
  if (feet == 0)
  {
    return Status::ok();
  }
  const auto footAt = [&](size_t f)
  {
    std::array<double, D> x;
    std::memcpy(x.data(), allFeet.data() + f * footBytes, footBytes);
    return x;
  };
  // The ranks' answers, each for the feet it owns, in the gathered order.
  std::vector<int> owner(feet);
  std::vector<double> answers;
  const Interp prototype(phi);
  CellCache<Interp, 1> interpolateAt(prototype, phi);
  const GridSpec<D>& window = phi.spec();
  Index misplaced = 0;
  for (size_t f = 0; f < feet; ++f)
  {
    const std::array<double, D> x = footAt(f);
    owner[f] = slabOwnerOfRow(boundaries, slabRowAt(whole, x[D - 1]));
    if (owner[f] == rank)
    {
      misplaced += footInWindow<Interp>(window, far, window.indexCoordinate(D - 1, x[D - 1])) ? 0 : 1;
      answers.push_back(interpolateAt(x.data()));
    }
  }
  Status status = misplaced == 0
    ? Status::ok()
    : Status::numericalFailure(std::to_string(misplaced) +
        " far feet of the SL step fall beyond their owner's ghost rows (an internal error)");
  SLTK_RETURN_IF_ERROR(comm.agree(status));
  std::vector<unsigned char> allAnswers;
  std::vector<std::int64_t> answerCounts;
  comm.allGatherV(answers.data(), answers.size() * sizeof(double), allAnswers, answerCounts);
  // Rank r's answers start at the sum of the earlier ranks' counts; they come in gathered order.
  std::vector<size_t> next(static_cast<size_t>(size), 0);
  for (int r = 1; r < size; ++r)
  {
    next[static_cast<size_t>(r)] =
      next[static_cast<size_t>(r) - 1] + static_cast<size_t>(answerCounts[static_cast<size_t>(r) - 1]) / sizeof(double);
  }
  size_t mineFirst = 0;
  for (int r = 0; r < rank; ++r)
  {
    mineFirst += static_cast<size_t>(counts[static_cast<size_t>(r)]) / footBytes;
  }
  const size_t mineEnd = mineFirst + far.Feet.size();
  for (size_t f = 0; f < mineEnd; ++f)
  {
    double value = 0.0;
    std::memcpy(&value, allAnswers.data() + next[static_cast<size_t>(owner[f])]++ * sizeof(double), sizeof(double));
    if (f >= mineFirst)
    {
      far.Values[static_cast<size_t>(far.Slots[f - mineFirst])] = value;
    }
  }
  return Status::ok();
}

} // namespace sltk
