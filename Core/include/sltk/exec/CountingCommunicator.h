// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CountingCommunicator.h
/// A communicator that forwards every call to another and counts this rank's
/// traffic (CommTraffic.h): the bytes it sends to other ranks point to point
/// (the halo exchanges of the slab decompositions, grid/SlabExchange.h; the
/// ghost tiles and migrations of the tiled band, all-to-all or to neighbours),
/// its payload of the collectives times the ranks it reaches, and its
/// collective calls (reductions, agreements, gathers; a neighbour exchange
/// counts as none). The distributed solvers report these per run
/// (Documentation/Distributed.md, "Communication volume per phase") so that a
/// scaling model rests on measured volumes, not estimates.

#include "sltk/exec/Communicator.h"

namespace sltk
{

class CountingCommunicator final : public Communicator
{
public:
  /// `inner` must outlive this communicator.
  explicit CountingCommunicator(const Communicator& inner)
    : Inner(&inner)
  {
  }

  /// Bytes this rank sent point to point so far (traffic() has every count).
  std::int64_t bytesSent() const { return this->Counted.PointToPointBytes; }
  CommTraffic traffic() const override { return this->Counted; }
  using Communicator::allGatherV;
  using Communicator::allReduce;

  int rank() const override { return this->Inner->rank(); }
  int size() const override { return this->Inner->size(); }
  void barrier() const override
  {
    this->collective(0);
    this->Inner->barrier();
  }
  void allReduce(double* values, std::size_t count, ReduceOp op) const override
  {
    this->collective(count * sizeof(double));
    this->Inner->allReduce(values, count, op);
  }
  void allReduce(std::int64_t* values, std::size_t count, ReduceOp op) const override
  {
    this->collective(count * sizeof(std::int64_t));
    this->Inner->allReduce(values, count, op);
  }
  void broadcast(void* bytes, std::size_t count, int root) const override
  {
    this->collective(root == this->rank() ? count : 0);
    this->Inner->broadcast(bytes, count, root);
  }
  void allGather(const void* bytes, std::size_t count, void* out) const override
  {
    this->collective(count);
    this->Inner->allGather(bytes, count, out);
  }
  void allGatherV(const void* bytes, std::size_t count, std::vector<unsigned char>& out,
    std::vector<std::int64_t>& counts) const override
  {
    this->collective(count);
    this->Inner->allGatherV(bytes, count, out, counts);
  }
  void allToAllV(const void* send, const std::vector<std::int64_t>& sendCounts, std::vector<unsigned char>& out,
    std::vector<std::int64_t>& receiveCounts) const override
  {
    this->collective(0); // its bytes go point to point, each to one rank
    for (size_t r = 0; r < sendCounts.size(); ++r)
    {
      this->Counted.PointToPointBytes += static_cast<int>(r) == this->rank() ? 0 : sendCounts[r];
    }
    this->Inner->allToAllV(send, sendCounts, out, receiveCounts);
  }
  bool neighbourExchange(const std::vector<Outgoing>& out, const std::vector<Incoming>& in) const override
  {
    for (const Outgoing& message : out)
    {
      this->Counted.PointToPointBytes += message.Rank == this->rank() ? 0 : static_cast<std::int64_t>(message.Count);
    }
    return this->Inner->neighbourExchange(out, in);
  }
  void sendReceive(const void* send, std::size_t sendBytes, int destination, void* receive, std::size_t receiveBytes,
    int source) const override
  {
    this->Counted.PointToPointBytes += destination >= 0 ? static_cast<std::int64_t>(sendBytes) : 0;
    this->Inner->sendReceive(send, sendBytes, destination, receive, receiveBytes, source);
  }
  void* nativeHandle() const override { return this->Inner->nativeHandle(); }

private:
  /// One collective call carrying `payload` bytes of this rank to each other rank.
  void collective(std::size_t payload) const
  {
    ++this->Counted.Collectives;
    this->Counted.CollectiveBytes += static_cast<std::int64_t>(payload) * (this->size() - 1);
  }

  const Communicator* Inner;
  mutable CommTraffic Counted;
};

/// Every count of each of `phases` (this rank's traffic per phase) at its largest over the
/// ranks: the busiest rank's traffic per phase, in one reduction (collective).
inline std::vector<CommTraffic> busiestRanks(std::vector<CommTraffic> phases, const Communicator& comm)
{
  std::vector<std::int64_t> counts;
  for (const CommTraffic& t : phases)
  {
    counts.insert(counts.end(), { t.PointToPointBytes, t.CollectiveBytes, t.Collectives });
  }
  comm.allReduce(counts.data(), counts.size(), ReduceOp::Max);
  for (size_t k = 0; k < phases.size(); ++k)
  {
    phases[k] = { counts[3 * k], counts[3 * k + 1], counts[3 * k + 2] };
  }
  return phases;
}

} // namespace sltk
