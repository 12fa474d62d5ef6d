// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "tasks/checked_tasks.h"

#include "core/report_error.h"
#include "meff/error.h"

#include <string>

namespace meff::detail
{

CheckedTasks::CheckedTasks(TaskSystem& user)
    : m_user(user), m_threadCount(user.ThreadCount()),
      m_busy(std::make_unique<std::atomic<bool>[]>(static_cast<std::size_t>(m_threadCount)))
{
}

void CheckedTasks::Refuse(const char* what, int begin, int end, int worker)
{
    if (m_refused.exchange(true, std::memory_order_relaxed))
    {
        return;
    }
    const std::lock_guard lock(m_refusalMutex);
    m_refusal = std::string(what) + " (range [" + std::to_string(begin) + ", " +
                std::to_string(end) + "), worker " + std::to_string(worker) + ")";
}

namespace
{
/// Clears a worker index's busy flag when the range that took it ends, normally or not.
class ReleaseOnExit
{
  public:
    explicit ReleaseOnExit(std::atomic<bool>& busy) : m_busy(busy) {}
    ~ReleaseOnExit() { m_busy.store(false, std::memory_order_release); }
    ReleaseOnExit(const ReleaseOnExit&) = delete;
    ReleaseOnExit& operator=(const ReleaseOnExit&) = delete;

  private:
    std::atomic<bool>& m_busy;
};
} // namespace

void CheckedTasks::ParallelFor(int count, int minRange,
                               FunctionRef<void(int begin, int end, int worker)> task)
{
    m_ran.store(0, std::memory_order_relaxed);
    m_moment.store(0, std::memory_order_relaxed);
    m_refused.store(false, std::memory_order_relaxed);
    const auto checked = [&](int begin, int end, int worker)
    {
        if (begin < 0 || end > count || begin > end)
        {
            Refuse("a range outside the job's indices", begin, end, worker);
            return;
        }
        if (worker < 0 || worker >= m_threadCount)
        {
            Refuse("a worker index outside [0, ThreadCount())", begin, end, worker);
            return;
        }
        std::atomic<bool>& busy = m_busy[static_cast<std::size_t>(worker)];
        if (busy.exchange(true, std::memory_order_acquire))
        {
            Refuse("a worker index that another range was running with at the same time", begin,
                   end, worker);
            return;
        }
        {
            // Freed however the task leaves (an allocation's bad_alloc in a task fails the step;
            // a later step on this world must not find the index still taken).
            const ReleaseOnExit release(busy);
            task(begin, end, worker);
        }
        const auto b = static_cast<std::uint64_t>(begin);
        const auto e = static_cast<std::uint64_t>(end);
        m_ran.fetch_add(end - begin, std::memory_order_relaxed);
        m_moment.fetch_add(e * e - b * b, std::memory_order_relaxed);
    };
    m_user.ParallelFor(count, minRange, checked);

    const auto n = static_cast<std::uint64_t>(count);
    std::string problem;
    if (m_refused.load(std::memory_order_acquire))
    {
        const std::lock_guard lock(m_refusalMutex);
        problem = "gave " + m_refusal;
    }
    else if (m_ran.load(std::memory_order_acquire) != count ||
             m_moment.load(std::memory_order_acquire) != n * n)
    {
        problem = "ran " + std::to_string(m_ran.load(std::memory_order_relaxed)) +
                  " indices, some of them not exactly once";
    }
    if (problem.empty())
    {
        return;
    }
    ReportFatalError(Error("TaskSystem::ParallelFor: a job of " + std::to_string(count) +
                           " indices " + problem + "; each index must run exactly once, with a " +
                           "worker index from 0 to " + std::to_string(m_threadCount - 1) +
                           " that no other range is running with (meff/task_system.h); the step "
                           "is left half done and the world is frozen (restore a snapshot)"));
}

} // namespace meff::detail
