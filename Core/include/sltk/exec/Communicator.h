// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Communicator.h
/// The communicator seam (Documentation/Architecture.md, "Communicator
/// seam"): the collective operations Core algorithms need across processes
/// (MPI ranks), with a serial implementation as the default, so that Core is
/// correct with one rank and no public header needs mpi.h. The MPI
/// implementation is SLTK::Mpi (Mpi/include/sltk/mpi/MpiCommunicator.h); the
/// filters build it from VTK's controller, the CLI from MPI directly.
///
/// Every operation is collective: all ranks call it, in the same order, with
/// the same counts where a count is said to be the same. A rank that fails
/// locally must still reach the next collective call; agree() is the call
/// that turns a failure on one rank into the same error on every rank, so
/// that no rank waits in a collective the failed rank never enters.

#include "sltk/core/Status.h"
#include "sltk/exec/CommTraffic.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

namespace sltk
{

enum class ReduceOp
{
  Sum,
  Min,
  Max
};

class Communicator
{
public:
  virtual ~Communicator() = default;

  virtual int rank() const = 0;
  virtual int size() const = 0;
  virtual void barrier() const = 0;

  /// In place, element-wise over the ranks: values[i] = op_r values_r[i].
  /// Every rank passes the same count. Sums of doubles are reduced in the
  /// implementation's order (MPI: not necessarily rank order), so a sum can
  /// differ in its last bits between rank counts; min and max are exact.
  virtual void allReduce(double* values, std::size_t count, ReduceOp op) const = 0;
  virtual void allReduce(std::int64_t* values, std::size_t count, ReduceOp op) const = 0;

  /// Copies `count` bytes of rank `root` into `bytes` on every rank (the same count everywhere).
  virtual void broadcast(void* bytes, std::size_t count, int root) const = 0;

  /// out = the `count` bytes of rank 0, then of rank 1, ... (the same count
  /// everywhere; out holds size() * count bytes).
  virtual void allGather(const void* bytes, std::size_t count, void* out) const = 0;

  /// out = every rank's bytes in rank order, counts[r] = bytes of rank r
  /// (counts may differ, and be 0).
  virtual void allGatherV(
    const void* bytes, std::size_t count, std::vector<unsigned char>& out, std::vector<std::int64_t>& counts) const = 0;

  /// Personalised all-to-all: `send` holds the bytes for rank 0, then for
  /// rank 1, ... (sendCounts[r] bytes for rank r, 0 allowed); `out` receives
  /// every rank's bytes for this rank in rank order, receiveCounts[r] from
  /// rank r. The ghost and migration exchanges of the distributed tiled band
  /// (Core/src/octree/TileDistribution.h).
  virtual void allToAllV(const void* send, const std::vector<std::int64_t>& sendCounts, std::vector<unsigned char>& out,
    std::vector<std::int64_t>& receiveCounts) const = 0;

  /// A message of a neighbour exchange: `count` bytes to or from rank `rank`.
  struct Outgoing
  {
    int Rank;
    const void* Bytes;
    std::size_t Count;
  };
  struct Incoming
  {
    int Rank;
    void* Bytes;
    std::size_t Count;
  };
  /// Sparse point-to-point exchange: every message of `out` goes to its rank,
  /// every message of `in` (its size known to the receiver) comes from its
  /// rank, at once (no order between them, no deadlock). The ranks must list
  /// matching pairs: a message from r to q in r's `out`, with the same count
  /// in q's `in`, in the same order per pair. Only the ranks that exchange
  /// wait for each other: the cost grows with the neighbours, not with size()
  /// (the ghost exchanges of Core/src/octree/TileDistribution.h). Serial: rank 0
  /// to itself, a copy. Returns false when a message came shorter than its
  /// Incoming count (the pairs disagree: an internal error of the caller).
  virtual bool neighbourExchange(const std::vector<Outgoing>& out, const std::vector<Incoming>& in) const = 0;

  /// Sends `sendBytes` bytes to rank `destination` and receives `receiveBytes`
  /// bytes from rank `source` at once (no deadlock when neighbours exchange in
  /// both directions); -1 as a rank skips that half. The halo exchange of a
  /// block decomposition (sltk/hjb/HjbSlabs.h). Serial: only -1 (or rank 0 to
  /// itself, a copy).
  virtual void sendReceive(const void* send, std::size_t sendBytes, int destination, void* receive,
    std::size_t receiveBytes, int source) const = 0;

  /// The implementation's native handle (SLTK::Mpi: a pointer to its
  /// MPI_Comm, which p4est takes); nullptr for the serial communicator.
  virtual void* nativeHandle() const { return nullptr; }

  /// This rank's traffic so far when it is counted (CountingCommunicator.h),
  /// else zeros: the runs read it at their start and end (RunFigures::Traffic).
  virtual CommTraffic traffic() const { return {}; }

  /// One value reduced over the ranks.
  double allReduce(double value, ReduceOp op) const
  {
    this->allReduce(&value, 1, op);
    return value;
  }
  std::int64_t allReduce(std::int64_t value, ReduceOp op) const
  {
    this->allReduce(&value, 1, op);
    return value;
  }
  /// Whether `local` holds on any rank: the loop tests every rank must take alike.
  bool anyRank(bool local) const { return this->allReduce(std::int64_t(local ? 1 : 0), ReduceOp::Max) > 0; }

  /// Every rank's elements, in rank order (T trivially copyable);
  /// `counts` (optional) receives the element count of every rank.
  template <class T>
  std::vector<T> allGatherV(const std::vector<T>& local, std::vector<std::int64_t>* counts = nullptr) const
  {
    static_assert(std::is_trivially_copyable<T>::value, "allGatherV sends raw bytes");
    std::vector<unsigned char> bytes;
    std::vector<std::int64_t> byteCounts;
    this->allGatherV(local.data(), local.size() * sizeof(T), bytes, byteCounts);
    std::vector<T> all(bytes.size() / sizeof(T));
    if (!all.empty())
    {
      std::memcpy(static_cast<void*>(all.data()), bytes.data(), bytes.size());
    }
    if (counts)
    {
      counts->clear();
      for (std::int64_t c : byteCounts)
      {
        counts->push_back(c / static_cast<std::int64_t>(sizeof(T)));
      }
    }
    return all;
  }

  /// A personalised all-to-all of records (T trivially copyable): `send`
  /// holds counts[0] records for rank 0, then counts[1] for rank 1, ...; the
  /// result every rank's records for this one in rank order, `received`
  /// (optional) their count from each rank.
  template <class T>
  std::vector<T> allToAllRecords(const std::vector<T>& send, const std::vector<std::int64_t>& counts,
    std::vector<std::int64_t>* received = nullptr) const
  {
    static_assert(std::is_trivially_copyable<T>::value, "allToAllRecords sends raw bytes");
    std::vector<std::int64_t> byteCounts(counts);
    for (std::int64_t& c : byteCounts)
    {
      c *= static_cast<std::int64_t>(sizeof(T));
    }
    std::vector<unsigned char> bytes;
    std::vector<std::int64_t> receivedBytes;
    this->allToAllV(send.data(), byteCounts, bytes, receivedBytes);
    std::vector<T> records(bytes.size() / sizeof(T));
    if (!records.empty())
    {
      std::memcpy(static_cast<void*>(records.data()), bytes.data(), records.size() * sizeof(T));
    }
    if (received)
    {
      received->clear();
      for (std::int64_t c : receivedBytes)
      {
        received->push_back(c / static_cast<std::int64_t>(sizeof(T)));
      }
    }
    return records;
  }

  /// The collective status agreement: every rank passes its own status and
  /// every rank receives the same one: ok when all are ok, otherwise the
  /// error of the lowest failing rank (code and message, the message
  /// prefixed with "rank R of N: " when there is more than one rank).
  Status agree(const Status& local) const;
};

/// The one-rank communicator (no MPI): every collective is a copy or nothing.
const Communicator& serialCommunicator();

/// A new serial communicator, for owners that hold any communicator by pointer.
std::unique_ptr<Communicator> newSerialCommunicator();

} // namespace sltk
