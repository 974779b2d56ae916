// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/exec/Communicator.h"
#include "sltk/exec/FirstError.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace sltk
{

Status agreeOnFirstError(const Communicator& comm, const Status& local, int* root)
{
  const int ranks = comm.size();
  if (root)
  {
    *root = local.isOk() ? ranks : comm.rank();
  }
  if (ranks == 1)
  {
    return local;
  }
  // The lowest failing rank, or `ranks` when every rank is ok.
  const std::int64_t first =
    comm.allReduce(static_cast<std::int64_t>(local.isOk() ? ranks : comm.rank()), ReduceOp::Min);
  if (root)
  {
    *root = static_cast<int>(first);
  }
  if (first == ranks)
  {
    return Status::ok();
  }
  const int from = static_cast<int>(first);
  std::int64_t header[2] = { static_cast<std::int64_t>(local.code()),
    static_cast<std::int64_t>(local.message().size()) };
  comm.broadcast(header, sizeof(header), from);
  std::string message(static_cast<size_t>(header[1]), '\0');
  if (comm.rank() == from)
  {
    message = local.message();
  }
  if (!message.empty())
  {
    comm.broadcast(&message[0], message.size(), from);
  }
  return Status(static_cast<StatusCode>(header[0]), message);
}

Status Communicator::agree(const Status& local) const
{
  int root = 0;
  const Status first = agreeOnFirstError(*this, local, &root);
  if (first.isOk() || this->size() == 1)
  {
    return first;
  }
  return Status(
    first.code(), "rank " + std::to_string(root) + " of " + std::to_string(this->size()) + ": " + first.message());
}

namespace
{
class SerialCommunicator final : public Communicator
{
public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void barrier() const override {}
  void allReduce(double*, std::size_t, ReduceOp) const override {}
  void allReduce(std::int64_t*, std::size_t, ReduceOp) const override {}
  void broadcast(void*, std::size_t, int) const override {}
  void allGather(const void* bytes, std::size_t count, void* out) const override
  {
    if (count)
    {
      std::memcpy(out, bytes, count);
    }
  }
  void allGatherV(const void* bytes, std::size_t count, std::vector<unsigned char>& out,
    std::vector<std::int64_t>& counts) const override
  {
    const auto* b = static_cast<const unsigned char*>(bytes);
    out.assign(b, b + count);
    counts.assign(1, static_cast<std::int64_t>(count));
  }
  void allToAllV(const void* send, const std::vector<std::int64_t>& sendCounts, std::vector<unsigned char>& out,
    std::vector<std::int64_t>& receiveCounts) const override
  {
    const auto* b = static_cast<const unsigned char*>(send);
    out.assign(b, b + sendCounts.at(0));
    receiveCounts.assign(1, sendCounts.at(0));
  }
  bool neighbourExchange(const std::vector<Outgoing>& out, const std::vector<Incoming>& in) const override
  {
    bool complete = out.size() == in.size();
    for (size_t k = 0; k < out.size() && k < in.size(); ++k)
    {
      complete = complete && out[k].Rank == 0 && in[k].Rank == 0 && out[k].Count == in[k].Count;
      if (out[k].Count && in[k].Count)
      {
        std::memcpy(in[k].Bytes, out[k].Bytes, std::min(out[k].Count, in[k].Count));
      }
    }
    return complete;
  }
  void sendReceive(const void* send, std::size_t sendBytes, int destination, void* receive, std::size_t receiveBytes,
    int source) const override
  {
    if (destination == 0 && source == 0)
    {
      std::memcpy(receive, send, std::min(sendBytes, receiveBytes));
    }
  }
};
} // namespace

const Communicator& serialCommunicator()
{
  static const SerialCommunicator serial;
  return serial;
}

std::unique_ptr<Communicator> newSerialCommunicator()
{
  return std::make_unique<SerialCommunicator>();
}

} // namespace sltk
