// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/mpi/MpiCommunicator.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdlib>

namespace sltk
{
namespace mpi
{

namespace
{
/// MPI counts are int: larger messages go in pieces of this many bytes.
constexpr std::size_t MaxChunk = static_cast<std::size_t>(INT_MAX);

MPI_Op toMpi(ReduceOp op)
{
  switch (op)
  {
    case ReduceOp::Sum:
      return MPI_SUM;
    case ReduceOp::Min:
      return MPI_MIN;
    case ReduceOp::Max:
      return MPI_MAX;
  }
  return MPI_SUM;
}

void finaliseAtExit()
{
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (!finalised)
  {
    MPI_Finalize();
  }
}
} // namespace

bool isMpiActive()
{
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}

Status ensureMpiInitialised()
{
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  if (finalised)
  {
    return Status::invalidArgument("MPI was already finalised in this process: octree and MPI work must run "
                                   "before MPI_Finalize");
  }
  if (!initialised)
  {
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    {
      return Status::invalidArgument("MPI_Init_thread failed: run the program under mpirun, or call MPI_Init first");
    }
    std::atexit(finaliseAtExit);
  }
  return Status::ok();
}

struct MpiCommunicator::Impl
{
  MPI_Comm Comm = MPI_COMM_NULL;
  int Rank = 0;
  int Size = 1;
};

MpiCommunicator::MpiCommunicator(std::unique_ptr<Impl> impl)
  : P(std::move(impl))
{
}

MpiCommunicator::~MpiCommunicator() = default;

Status MpiCommunicator::fromHandle(void* mpiCommPointer, std::unique_ptr<MpiCommunicator>& out)
{
  out.reset();
  if (!isMpiActive())
  {
    return Status::invalidArgument(
      "MPI is not initialised: call MPI_Init (mpirun programs, pvbatch and pvpython do) before building an MPI "
      "communicator");
  }
  if (!mpiCommPointer || *static_cast<MPI_Comm*>(mpiCommPointer) == MPI_COMM_NULL)
  {
    return Status::invalidArgument("null MPI communicator handle: pass a pointer to a valid MPI_Comm");
  }
  auto impl = std::make_unique<Impl>();
  impl->Comm = *static_cast<MPI_Comm*>(mpiCommPointer);
  MPI_Comm_rank(impl->Comm, &impl->Rank);
  MPI_Comm_size(impl->Comm, &impl->Size);
  out.reset(new MpiCommunicator(std::move(impl)));
  return Status::ok();
}

Status MpiCommunicator::world(std::unique_ptr<MpiCommunicator>& out)
{
  MPI_Comm comm = MPI_COMM_WORLD;
  return fromHandle(&comm, out);
}

Status MpiCommunicator::self(std::unique_ptr<MpiCommunicator>& out)
{
  MPI_Comm comm = MPI_COMM_SELF;
  return fromHandle(&comm, out);
}

int MpiCommunicator::rank() const
{
  return this->P->Rank;
}

int MpiCommunicator::size() const
{
  return this->P->Size;
}

void MpiCommunicator::barrier() const
{
  MPI_Barrier(this->P->Comm);
}

void MpiCommunicator::allReduce(double* values, std::size_t count, ReduceOp op) const
{
  for (std::size_t done = 0; done < count;)
  {
    const std::size_t n = std::min(count - done, MaxChunk / sizeof(double));
    MPI_Allreduce(MPI_IN_PLACE, values + done, static_cast<int>(n), MPI_DOUBLE, toMpi(op), this->P->Comm);
    done += n;
  }
}

void MpiCommunicator::allReduce(std::int64_t* values, std::size_t count, ReduceOp op) const
{
  for (std::size_t done = 0; done < count;)
  {
    const std::size_t n = std::min(count - done, MaxChunk / sizeof(std::int64_t));
    MPI_Allreduce(MPI_IN_PLACE, values + done, static_cast<int>(n), MPI_INT64_T, toMpi(op), this->P->Comm);
    done += n;
  }
}

void MpiCommunicator::broadcast(void* bytes, std::size_t count, int root) const
{
  auto* b = static_cast<unsigned char*>(bytes);
  for (std::size_t done = 0; done < count;)
  {
    const std::size_t n = std::min(count - done, MaxChunk);
    MPI_Bcast(b + done, static_cast<int>(n), MPI_BYTE, root, this->P->Comm);
    done += n;
  }
}

void MpiCommunicator::sendReceive(
  const void* send, std::size_t sendBytes, int destination, void* receive, std::size_t receiveBytes, int source) const
{
  const int to = destination < 0 ? MPI_PROC_NULL : destination;
  const int from = source < 0 ? MPI_PROC_NULL : source;
  const auto* out = static_cast<const unsigned char*>(send);
  auto* in = static_cast<unsigned char*>(receive);
  // In chunks that fit an int count; both sides agree on the sizes (the same rows).
  const std::size_t total = std::max(destination < 0 ? 0 : sendBytes, source < 0 ? 0 : receiveBytes);
  for (std::size_t done = 0; done < total || done == 0; done += MaxChunk)
  {
    const std::size_t sendNow = destination < 0 || done >= sendBytes ? 0 : std::min(sendBytes - done, MaxChunk);
    const std::size_t receiveNow = source < 0 || done >= receiveBytes ? 0 : std::min(receiveBytes - done, MaxChunk);
    MPI_Sendrecv(out + (sendNow ? done : 0), static_cast<int>(sendNow), MPI_BYTE, to, 0, in + (receiveNow ? done : 0),
      static_cast<int>(receiveNow), MPI_BYTE, from, 0, this->P->Comm, MPI_STATUS_IGNORE);
    if (total == 0)
    {
      break;
    }
  }
}

void MpiCommunicator::allGather(const void* bytes, std::size_t count, void* out) const
{
  std::vector<unsigned char> received;
  std::vector<std::int64_t> counts;
  this->allGatherV(bytes, count, received, counts);
  if (!received.empty())
  {
    std::memcpy(out, received.data(), received.size());
  }
}

void MpiCommunicator::allGatherV(
  const void* bytes, std::size_t count, std::vector<unsigned char>& out, std::vector<std::int64_t>& counts) const
{
  const int ranks = this->P->Size;
  counts.assign(static_cast<size_t>(ranks), 0);
  const std::int64_t mine = static_cast<std::int64_t>(count);
  MPI_Allgather(&mine, 1, MPI_INT64_T, counts.data(), 1, MPI_INT64_T, this->P->Comm);
  std::vector<std::int64_t> offsets(static_cast<size_t>(ranks) + 1, 0);
  for (int r = 0; r < ranks; ++r)
  {
    offsets[static_cast<size_t>(r) + 1] = offsets[static_cast<size_t>(r)] + counts[static_cast<size_t>(r)];
  }
  out.assign(static_cast<size_t>(offsets.back()), 0);
  // Rounds in which every rank sends at most `chunk` bytes, so that every
  // count and displacement of one MPI_Allgatherv fits in an int.
  const std::int64_t chunk = static_cast<std::int64_t>(MaxChunk) / ranks;
  const std::int64_t largest = *std::max_element(counts.begin(), counts.end());
  std::vector<int> sizes(static_cast<size_t>(ranks)), displacements(static_cast<size_t>(ranks));
  std::vector<unsigned char> round;
  const auto* b = static_cast<const unsigned char*>(bytes);
  for (std::int64_t start = 0; start < largest; start += chunk)
  {
    int total = 0;
    for (int r = 0; r < ranks; ++r)
    {
      const std::int64_t c = counts[static_cast<size_t>(r)];
      sizes[static_cast<size_t>(r)] = static_cast<int>(std::clamp<std::int64_t>(c - start, 0, chunk));
      displacements[static_cast<size_t>(r)] = total;
      total += sizes[static_cast<size_t>(r)];
    }
    round.resize(static_cast<size_t>(total));
    const int mineNow = sizes[static_cast<size_t>(this->P->Rank)];
    MPI_Allgatherv(mineNow ? b + start : b, mineNow, MPI_BYTE, round.data(), sizes.data(), displacements.data(),
      MPI_BYTE, this->P->Comm);
    for (int r = 0; r < ranks; ++r)
    {
      std::copy_n(round.data() + displacements[static_cast<size_t>(r)], sizes[static_cast<size_t>(r)],
        out.data() + offsets[static_cast<size_t>(r)] + start);
    }
  }
}

void MpiCommunicator::allToAllV(const void* send, const std::vector<std::int64_t>& sendCounts,
  std::vector<unsigned char>& out, std::vector<std::int64_t>& receiveCounts) const
{
  const int ranks = this->P->Size;
  receiveCounts.assign(static_cast<size_t>(ranks), 0);
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT64_T, receiveCounts.data(), 1, MPI_INT64_T, this->P->Comm);
  std::vector<std::int64_t> sendOffsets(static_cast<size_t>(ranks) + 1, 0), receiveOffsets(sendOffsets);
  for (int r = 0; r < ranks; ++r)
  {
    sendOffsets[static_cast<size_t>(r) + 1] = sendOffsets[static_cast<size_t>(r)] + sendCounts[static_cast<size_t>(r)];
    receiveOffsets[static_cast<size_t>(r) + 1] =
      receiveOffsets[static_cast<size_t>(r)] + receiveCounts[static_cast<size_t>(r)];
  }
  out.assign(static_cast<size_t>(receiveOffsets.back()), 0);
  // Rounds in which every pair moves at most `chunk` bytes, so that every
  // count and displacement of one MPI_Alltoallv fits in an int.
  const std::int64_t chunk = static_cast<std::int64_t>(MaxChunk) / ranks;
  std::int64_t largest = 0;
  for (int r = 0; r < ranks; ++r)
  {
    largest = std::max({ largest, sendCounts[static_cast<size_t>(r)], receiveCounts[static_cast<size_t>(r)] });
  }
  largest = this->allReduce(largest, ReduceOp::Max); // every rank takes part in every round
  std::vector<int> sendSizes(static_cast<size_t>(ranks)), sendAt(sendSizes), receiveSizes(sendSizes),
    receiveAt(sendSizes);
  std::vector<unsigned char> outRound, inRound;
  const auto* b = static_cast<const unsigned char*>(send);
  for (std::int64_t start = 0; start < largest; start += chunk)
  {
    int sendTotal = 0, receiveTotal = 0;
    for (int r = 0; r < ranks; ++r)
    {
      const size_t k = static_cast<size_t>(r);
      sendSizes[k] = static_cast<int>(std::clamp<std::int64_t>(sendCounts[k] - start, 0, chunk));
      sendAt[k] = sendTotal;
      sendTotal += sendSizes[k];
      receiveSizes[k] = static_cast<int>(std::clamp<std::int64_t>(receiveCounts[k] - start, 0, chunk));
      receiveAt[k] = receiveTotal;
      receiveTotal += receiveSizes[k];
    }
    outRound.resize(static_cast<size_t>(std::max(sendTotal, 1)));
    inRound.resize(static_cast<size_t>(std::max(receiveTotal, 1)));
    for (int r = 0; r < ranks; ++r)
    {
      const size_t k = static_cast<size_t>(r);
      std::copy_n(b + sendOffsets[k] + (sendSizes[k] ? start : 0), sendSizes[k], outRound.data() + sendAt[k]);
    }
    MPI_Alltoallv(outRound.data(), sendSizes.data(), sendAt.data(), MPI_BYTE, inRound.data(), receiveSizes.data(),
      receiveAt.data(), MPI_BYTE, this->P->Comm);
    for (int r = 0; r < ranks; ++r)
    {
      const size_t k = static_cast<size_t>(r);
      if (receiveSizes[k] > 0)
      {
        std::copy_n(inRound.data() + receiveAt[k], receiveSizes[k], out.data() + receiveOffsets[k] + start);
      }
    }
  }
}

bool MpiCommunicator::neighbourExchange(const std::vector<Outgoing>& out, const std::vector<Incoming>& in) const
{
  // A message above an int count goes in chunks, each with its own tag (the
  // chunk's number); an empty message is one empty chunk.
  constexpr int Tag = 7700;
  std::vector<MPI_Request> requests;
  const auto post = [&](void* bytes, std::size_t count, int rank, bool receive)
  {
    auto* b = static_cast<unsigned char*>(bytes);
    const std::size_t chunks = std::max<std::size_t>(1, (count + MaxChunk - 1) / MaxChunk);
    for (std::size_t c = 0; c < chunks; ++c)
    {
      const std::size_t at = c * MaxChunk, n = std::min(MaxChunk, count - std::min(at, count));
      requests.emplace_back();
      if (receive)
      {
        MPI_Irecv(b + (n ? at : 0), static_cast<int>(n), MPI_BYTE, rank, Tag + static_cast<int>(c), this->P->Comm,
          &requests.back());
      }
      else
      {
        MPI_Isend(b + (n ? at : 0), static_cast<int>(n), MPI_BYTE, rank, Tag + static_cast<int>(c), this->P->Comm,
          &requests.back());
      }
    }
  };
  for (const Incoming& message : in)
  {
    post(message.Bytes, message.Count, message.Rank, true);
  }
  for (const Outgoing& message : out)
  {
    post(const_cast<void*>(message.Bytes), message.Count, message.Rank, false); // MPI_Isend reads only
  }
  std::vector<MPI_Status> statuses(requests.size());
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), statuses.data());
  // The receives were posted first: their statuses come first, in chunk order.
  bool complete = true;
  size_t r = 0;
  for (const Incoming& message : in)
  {
    const std::size_t chunks = std::max<std::size_t>(1, (message.Count + MaxChunk - 1) / MaxChunk);
    for (std::size_t c = 0; c < chunks; ++c, ++r)
    {
      const std::size_t at = c * MaxChunk, expected = std::min(MaxChunk, message.Count - std::min(at, message.Count));
      int got = 0;
      MPI_Get_count(&statuses[r], MPI_BYTE, &got);
      complete = complete && static_cast<std::size_t>(got) == expected;
    }
  }
  return complete;
}

void* MpiCommunicator::nativeHandle() const
{
  return &this->P->Comm;
}

} // namespace mpi
} // namespace sltk
