// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CommTraffic.h
/// What one rank sent to the others so far (CountingCommunicator.h), split so
/// that a scaling model can treat each kind by its own law
/// (Documentation/Distributed.md, "Communication volume per phase"):
///  - point-to-point bytes: the ghost exchanges of the slabs, the neighbour
///    exchanges and all-to-alls of the tiled band, each byte counted once;
///  - collective bytes: this rank's payload of every gather, broadcast (at its
///    root) and reduction times the other ranks it reaches (size() - 1), the
///    volume whatever algorithm the MPI library uses;
///  - collective calls (a neighbour exchange is none), whose latency adds up.

#include <cstdint>

namespace sltk
{

struct CommTraffic
{
  std::int64_t PointToPointBytes = 0;
  std::int64_t CollectiveBytes = 0;
  std::int64_t Collectives = 0;

  /// The traffic between two readings of one rank's counters (`earlier` first).
  CommTraffic since(const CommTraffic& earlier) const
  {
    return { this->PointToPointBytes - earlier.PointToPointBytes, this->CollectiveBytes - earlier.CollectiveBytes,
      this->Collectives - earlier.Collectives };
  }
};

} // namespace sltk
