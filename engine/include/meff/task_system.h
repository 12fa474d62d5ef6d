// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Threads for the step: the engine hands a range of independent work to a TaskSystem and waits
// for it. A game with its own job system implements TaskSystem over it (as Box2D v3's
// enqueueTask/finishTask callbacks); otherwise MakeThreadPool gives a default pool on
// std::thread. A world uses one through World::SetTaskSystem.
//
// Results never depend on the thread count: the engine only hands over work whose pieces write
// disjoint memory and combines per-piece results in a fixed order, so a world steps bit for bit
// alike on 1 thread or 8 (tests/test_threads.cpp).
#pragma once

#include "meff/function_ref.h"

#include <memory>

namespace meff
{

/// Threads a world may use for its steps (World::SetTaskSystem): a game routes the two calls
/// to its own job system, or takes MakeThreadPool's.
class TaskSystem
{
  public:
    virtual ~TaskSystem() = default;

    /// How many threads take part in ParallelFor, the calling thread included (1 to 1024):
    /// worker indices run from 0 to ThreadCount() − 1. It must not change while a world uses it
    /// (World::Step refuses to step when it has).
    virtual int ThreadCount() const = 0;

    /// Runs task(begin, end, worker) over ranges that together cover [0, count) exactly once,
    /// each at least `minRange` long (the last may be shorter), and returns when all are done.
    /// `worker` is the index, in [0, ThreadCount()), of the thread running that range: no two
    /// ranges run at the same time with one index, so per-worker scratch needs no lock. Ranges
    /// may run in any order and on any thread, the calling thread included. The task does not
    /// throw. Called from one thread at a time (the thread stepping the world). A world checks
    /// the ranges it is given (World::SetTaskSystem): a range outside [0, count), a worker index
    /// outside [0, ThreadCount()) or in use by a range running at the same moment, or an index
    /// run other than once, stops the step with an Error.
    virtual void ParallelFor(int count, int minRange,
                             FunctionRef<void(int begin, int end, int worker)> task) = 0;

  protected:
    TaskSystem() = default;
    /// Copyable by the classes that implement it.
    TaskSystem(const TaskSystem&) = default;
    /// Copyable by the classes that implement it.
    TaskSystem& operator=(const TaskSystem&) = default;
};

/// A pool of `threads` − 1 std::threads that, with the thread calling ParallelFor, share each
/// range of work (threads ≥ 1; 1 runs everything on the caller). Threads wait on a condition
/// variable between jobs, after a short spin. A job allocates nothing. Destroying the pool
/// joins its threads; it must not be destroyed during a ParallelFor. A count outside 1 to 1024
/// is refused (InvalidArgument; without exceptions, reported and nullptr returned).
std::unique_ptr<TaskSystem> MakeThreadPool(int threads);

} // namespace meff
