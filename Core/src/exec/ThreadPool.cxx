// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/exec/ThreadPool.h"

#include "sltk/exec/Memory.h"

#include <algorithm>
#include <cstdlib>
#ifdef __linux__
#include <sched.h>
#endif

namespace sltk
{

namespace
{
/// The cores this process may run on: its CPU affinity where the system tells
/// it (mpirun's --bind-to narrows it), else the machine's.
int usableCores()
{
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0 && CPU_COUNT(&set) > 0)
  {
    return CPU_COUNT(&set);
  }
#endif
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}
} // namespace

int threadsPerRank(int requested, int ranks)
{
  if (requested > 0)
  {
    return requested;
  }
  int threads = std::max(1, usableCores() / ranksSharingThisMachine(ranks));
  if (const char* cap = std::getenv("VTK_SMP_MAX_THREADS"))
  {
    const int most = std::atoi(cap);
    threads = most > 0 ? std::min(threads, most) : threads;
  }
  return threads;
}

ThreadPool::ThreadPool(int threads)
{
  if (threads <= 0)
  {
    threads = threadsPerRank(0);
  }
  this->Workers.reserve(static_cast<size_t>(threads - 1));
  for (int t = 1; t < threads; ++t)
  {
    this->Workers.emplace_back([this] { this->workerLoop(); });
  }
}

ThreadPool::~ThreadPool()
{
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Stopping = true;
  }
  this->WorkReady.notify_all();
  for (auto& w : this->Workers)
  {
    w.join();
  }
}

Index ThreadPool::effectiveGrain(Index begin, Index end, Index grain)
{
  if (grain > 0)
  {
    return grain;
  }
  // Independent of the thread count (determinism): about 64 chunks, at least 16 items each.
  const Index n = end - begin;
  return std::max<Index>(16, (n + 63) / 64);
}

Index ThreadPool::chunkCount(Index begin, Index end, Index grain)
{
  if (end <= begin)
  {
    return 0;
  }
  grain = effectiveGrain(begin, end, grain);
  return (end - begin + grain - 1) / grain;
}

void ThreadPool::run(Index chunks, const std::function<void(Index)>& task)
{
  if (this->Workers.empty() || chunks == 1)
  {
    for (Index c = 0; c < chunks; ++c)
    {
      task(c);
    }
    return;
  }
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Task = &task;
    this->Chunks = chunks;
    this->NextChunk = 0;
    this->Finished = 0;
    ++this->Generation;
  }
  this->WorkReady.notify_all();
  // The calling thread works too.
  for (;;)
  {
    Index c;
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      if (this->NextChunk >= this->Chunks)
      {
        break;
      }
      c = this->NextChunk++;
    }
    task(c);
    std::lock_guard<std::mutex> lock(this->Mutex);
    ++this->Finished;
  }
  std::unique_lock<std::mutex> lock(this->Mutex);
  this->WorkDone.wait(lock, [this] { return this->Finished == this->Chunks; });
  this->Task = nullptr;
}

void ThreadPool::workerLoop()
{
  std::uint64_t seen = 0;
  std::unique_lock<std::mutex> lock(this->Mutex);
  for (;;)
  {
    this->WorkReady.wait(lock, [&] { return this->Stopping || this->Generation != seen; });
    if (this->Stopping)
    {
      return;
    }
    seen = this->Generation;
    while (this->Task && this->NextChunk < this->Chunks)
    {
      const Index c = this->NextChunk++;
      const auto* task = this->Task;
      lock.unlock();
      (*task)(c);
      lock.lock();
      if (++this->Finished == this->Chunks)
      {
        this->WorkDone.notify_all();
      }
    }
  }
}

} // namespace sltk
