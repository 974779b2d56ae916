// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ThreadPool.h
/// Core's own executor (Documentation/Architecture.md, "Threading": Debian's VTK defaults
/// vtkSMPTools to Sequential, so Core owns its pool).
///
/// parallelFor splits [begin, end) into chunks whose boundaries depend only on
/// the range and the grain, never on the number of threads (with a grain given,
/// chunk c is [begin + c grain, min(begin + (c + 1) grain, end)), which callers
/// index by (b - begin) / grain); parallelSum adds the chunk partials in chunk
/// order. Hence results are bit-identical between 1 and N threads.

#include "sltk/core/Index.h"

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sltk
{

/// The threads one of `ranks` MPI ranks runs, the one rule of every front end
/// (filters, plugin, CLI, pvbatch, pvserver): `requested` when it is > 0 (the
/// NumberOfThreads property, --threads); else the cores this process may run
/// on (its CPU affinity, which the launcher's binding narrows) shared equally
/// among the ranks on this machine (ranksSharingThisMachine, Memory.h), at
/// least 1, and at most VTK_SMP_MAX_THREADS when that is set to a positive
/// number (the cap VTK users set for vtkSMPTools).
int threadsPerRank(int requested, int ranks = 1);

class ThreadPool
{
public:
  /// `threads` <= 0 means threadsPerRank(0): every core this process may use,
  /// at most VTK_SMP_MAX_THREADS.
  explicit ThreadPool(int threads = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  /// Number of threads that execute work, including the calling thread.
  int size() const { return static_cast<int>(this->Workers.size()) + 1; }

  /// Number of chunks parallelFor uses for [begin, end) with this grain.
  static Index chunkCount(Index begin, Index end, Index grain);

  /// Calls body(chunkBegin, chunkEnd) over disjoint chunks covering [begin, end).
  /// `grain` is the chunk size (0: a size chosen from the range only).
  /// The body is called once per chunk, so it may keep per-chunk scratch.
  template <class Body>
  void parallelFor(Index begin, Index end, Body&& body, Index grain = 0)
  {
    if (end <= begin)
    {
      return;
    }
    grain = effectiveGrain(begin, end, grain);
    const Index chunks = (end - begin + grain - 1) / grain;
    auto chunkBody = [&](Index c)
    {
      const Index b = begin + c * grain;
      body(b, b + grain < end ? b + grain : end);
    };
    this->run(chunks, chunkBody);
  }

  /// Deterministic sum of body(chunkBegin, chunkEnd) over the chunks.
  template <class Body>
  double parallelSum(Index begin, Index end, Body&& body, Index grain = 0)
  {
    if (end <= begin)
    {
      return 0.0;
    }
    grain = effectiveGrain(begin, end, grain);
    const Index chunks = (end - begin + grain - 1) / grain;
    std::vector<double> partial(static_cast<size_t>(chunks), 0.0);
    auto chunkBody = [&](Index c)
    {
      const Index b = begin + c * grain;
      partial[static_cast<size_t>(c)] = body(b, b + grain < end ? b + grain : end);
    };
    this->run(chunks, chunkBody);
    double sum = 0.0;
    for (double p : partial)
    {
      sum += p;
    }
    return sum;
  }

private:
  static Index effectiveGrain(Index begin, Index end, Index grain);
  /// Runs task(c) for c in [0, chunks) on all threads; returns when all are done.
  void run(Index chunks, const std::function<void(Index)>& task);
  void workerLoop();

  std::vector<std::thread> Workers;
  std::mutex Mutex;
  std::condition_variable WorkReady;
  std::condition_variable WorkDone;
  const std::function<void(Index)>* Task = nullptr;
  Index Chunks = 0;
  Index NextChunk = 0;
  Index Finished = 0;
  std::uint64_t Generation = 0;
  bool Stopping = false;
};

} // namespace sltk
