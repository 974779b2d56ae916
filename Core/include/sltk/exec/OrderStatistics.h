// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file OrderStatistics.h
/// The k-th smallest of values spread over the ranks, without gathering them:
/// a bisection over the doubles' order (their bits, mapped so that integer
/// order is numeric order), one count reduced over the ranks per bit. The
/// median of a statistic over a cloud spread over ranks (the outlier test's
/// gate, CloudOutliers.h) is then the one-rank value.

#include "sltk/exec/Communicator.h"

#include <cstdint>
#include <vector>

namespace sltk
{

/// The value of rank k (0-based: k = 0 the smallest) among every rank's finite
/// `local` values (0 <= k < their total count; -0 and +0 count as distinct,
/// -0 first; on one rank a selection, which may return either zero). Collective:
/// the same value on every rank, 64 reductions.
double kthSmallestOverRanks(const std::vector<double>& local, std::int64_t k, const Communicator& comm);

} // namespace sltk
