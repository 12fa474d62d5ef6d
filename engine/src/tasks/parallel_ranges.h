// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// How the engine hands work to the world's TaskSystem (task_system.h), if it has one.
#pragma once

#include "meff/error.h"
#include "meff/task_system.h"

#include <exception>

namespace meff::detail
{

/// Runs f(begin, end, worker) over ranges covering [0, count) exactly once: on `tasks` when
/// there is one and enough work for two ranges of `minRange`, otherwise at once on the calling
/// thread as worker 0. f must only write what no other index of [0, count) writes, or memory of
/// its own worker.
template <typename F>
void ForRanges(TaskSystem* tasks, int count, int minRange, F&& f)
{
    if (count <= 0)
    {
        return;
    }
    if (tasks == nullptr || count < 2 * minRange)
    {
        f(0, count, 0);
        return;
    }
    tasks->ParallelFor(count, minRange, f);
}

/// Runs alone() once and f(begin, end, worker) over ranges covering [0, count) exactly once
/// (ForRanges), at the same time on `tasks`: a serial piece of work done beside independent
/// ranges, so that the other threads need not wait for it. The thread that takes the first range
/// runs alone() before it, perhaps a pool thread, so alone must not hand work to `tasks` itself.
/// alone must not touch what f writes, nor f what alone writes. alone may throw (it may
/// allocate); its exception is rethrown here once every range is done (a task must not throw).
/// Without exceptions (MEFF_EXCEPTIONS=0) nothing is caught.
template <typename Alone, typename F>
void ForRangesBeside(TaskSystem* tasks, int count, int minRange, Alone&& alone, F&& f)
{
#if MEFF_EXCEPTIONS
    std::exception_ptr failure;
    const auto runAlone = [&]
    {
        try
        {
            alone();
        }
        catch (...)
        {
            failure = std::current_exception();
        }
    };
#else
    const auto runAlone = [&] { alone(); };
#endif
    ForRanges(tasks, count + 1, minRange,
              [&](int begin, int end, int worker)
              {
                  if (begin == 0)
                  {
                      runAlone();
                      begin = 1;
                  }
                  if (begin < end)
                  {
                      f(begin - 1, end - 1, worker);
                  }
              });
#if MEFF_EXCEPTIONS
    if (failure)
    {
        std::rethrow_exception(failure);
    }
#endif
}

/// Runs f(i) for each i of [0, count) on `tasks` (ForRanges): for loops whose every index writes
/// only its own memory.
template <typename F>
void ForEachIndex(TaskSystem* tasks, int count, int minRange, F&& f)
{
    ForRanges(tasks, count, minRange,
              [&](int begin, int end, int)
              {
                  for (int i = begin; i < end; ++i)
                  {
                      f(i);
                  }
              });
}

/// Threads that may run the world's work at once (worker indices 0 to this − 1).
inline int WorkerCount(const TaskSystem* tasks)
{
    return tasks == nullptr ? 1 : tasks->ThreadCount();
}

} // namespace meff::detail
