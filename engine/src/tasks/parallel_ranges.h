// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// How the engine hands work to the world's TaskSystem (task_system.h), if it has one.
#pragma once

#include "meff/error.h"
#include "meff/task_system.h"

#include <algorithm>
#include <cstdint>
#include <exception>
#include <vector>

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

/// The indices one piece of StableCompact hands out: fixed, so that the pieces (and what they
/// count) are the same for any thread count.
inline constexpr int kCompactPiece = 1024;

/// A serial loop's `for (i < count) if (keep(i)) emit(i, kept++);` on `tasks`: every piece of
/// kCompactPiece indices first counts what it keeps, then, from the count of the pieces before
/// it, emits its kept indices with the positions the serial loop gives them. keep is called
/// twice for each index, so it must answer the same both times and write, if anything, only
/// what index i alone owns, the same both times; emit must only write what position and index
/// own. `pieceCounts` is scratch. Returns the number kept.
template <typename Keep, typename Emit>
std::int32_t StableCompact(TaskSystem* tasks, int count, std::vector<std::int32_t>& pieceCounts,
                           Keep&& keep, Emit&& emit)
{
    const int pieces = (count + kCompactPiece - 1) / kCompactPiece;
    pieceCounts.resize(static_cast<std::size_t>(pieces));
    ForEachIndex(tasks, pieces, 2,
                 [&](int piece)
                 {
                     std::int32_t kept = 0;
                     const int end = std::min(count, (piece + 1) * kCompactPiece);
                     for (int i = piece * kCompactPiece; i < end; ++i)
                     {
                         kept += keep(i) ? 1 : 0;
                     }
                     pieceCounts[static_cast<std::size_t>(piece)] = kept;
                 });
    std::int32_t total = 0;
    for (std::int32_t& n : pieceCounts)
    {
        const std::int32_t first = total;
        total += n;
        n = first;
    }
    ForEachIndex(tasks, pieces, 2,
                 [&](int piece)
                 {
                     std::int32_t position = pieceCounts[static_cast<std::size_t>(piece)];
                     const int end = std::min(count, (piece + 1) * kCompactPiece);
                     for (int i = piece * kCompactPiece; i < end; ++i)
                     {
                         if (keep(i))
                         {
                             emit(i, position++);
                         }
                     }
                 });
    return total;
}

/// Threads that may run the world's work at once (worker indices 0 to this − 1).
inline int WorkerCount(const TaskSystem* tasks)
{
    return tasks == nullptr ? 1 : tasks->ThreadCount();
}

} // namespace meff::detail
