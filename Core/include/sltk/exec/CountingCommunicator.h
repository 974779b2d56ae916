// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CountingCommunicator.h
/// A communicator that forwards every call to another and counts this rank's
/// traffic: the bytes it sends to other ranks (the halo exchanges of the slab
/// decompositions, grid/SlabExchange.h; the ghost tiles and migrations of the
/// tiled band, all-to-all or to neighbours) and the collective calls it makes
/// (reductions, agreements, gathers; a neighbour exchange counts as none). The distributed solvers report these
/// (Documentation/Distributed.md, "Communication volume") so that a scaling
/// model rests on measured volumes, not estimates.

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

  /// Bytes this rank sent point to point, and its collective calls, so far.
  std::int64_t bytesSent() const { return this->Sent; }
  std::int64_t collectives() const { return this->Collectives; }

  int rank() const override { return this->Inner->rank(); }
  int size() const override { return this->Inner->size(); }
  void barrier() const override
  {
    ++this->Collectives;
    this->Inner->barrier();
  }
  void allReduce(double* values, std::size_t count, ReduceOp op) const override
  {
    ++this->Collectives;
    this->Inner->allReduce(values, count, op);
  }
  void allReduce(std::int64_t* values, std::size_t count, ReduceOp op) const override
  {
    ++this->Collectives;
    this->Inner->allReduce(values, count, op);
  }
  void broadcast(void* bytes, std::size_t count, int root) const override
  {
    ++this->Collectives;
    this->Inner->broadcast(bytes, count, root);
  }
  void allGather(const void* bytes, std::size_t count, void* out) const override
  {
    ++this->Collectives;
    this->Inner->allGather(bytes, count, out);
  }
  void allGatherV(const void* bytes, std::size_t count, std::vector<unsigned char>& out,
    std::vector<std::int64_t>& counts) const override
  {
    ++this->Collectives;
    this->Inner->allGatherV(bytes, count, out, counts);
  }
  void allToAllV(const void* send, const std::vector<std::int64_t>& sendCounts, std::vector<unsigned char>& out,
    std::vector<std::int64_t>& receiveCounts) const override
  {
    ++this->Collectives;
    for (size_t r = 0; r < sendCounts.size(); ++r)
    {
      this->Sent += static_cast<int>(r) == this->rank() ? 0 : sendCounts[r];
    }
    this->Inner->allToAllV(send, sendCounts, out, receiveCounts);
  }
  bool neighbourExchange(const std::vector<Outgoing>& out, const std::vector<Incoming>& in) const override
  {
    for (const Outgoing& message : out)
    {
      this->Sent += message.Rank == this->rank() ? 0 : static_cast<std::int64_t>(message.Count);
    }
    return this->Inner->neighbourExchange(out, in);
  }
  void sendReceive(const void* send, std::size_t sendBytes, int destination, void* receive, std::size_t receiveBytes,
    int source) const override
  {
    this->Sent += destination >= 0 ? static_cast<std::int64_t>(sendBytes) : 0;
    this->Inner->sendReceive(send, sendBytes, destination, receive, receiveBytes, source);
  }
  void* nativeHandle() const override { return this->Inner->nativeHandle(); }

private:
  const Communicator* Inner;
  mutable std::int64_t Sent = 0;
  mutable std::int64_t Collectives = 0;
};

} // namespace sltk
