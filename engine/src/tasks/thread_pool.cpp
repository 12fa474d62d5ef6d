// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The default TaskSystem (task_system.h): threads − 1 std::threads plus the calling thread.
//
// A job is cut into pieces of `range` indices. Pieces are handed out by one 64-bit atomic
// cursor, (generation << 32) | next piece, taken by compare-and-swap: a worker that read job G
// and comes late, when job G+1 is already running, finds another generation in the cursor and
// takes nothing, so it can never run a piece of the new job with the old job's task. The
// job's description is published under the mutex with its generation; workers spin a little on
// the generation (the solver's jobs follow each other within microseconds) and then sleep on a
// condition variable. A job allocates nothing: the task is a FunctionRef on the caller's
// stack, which outlives the job because the caller waits for its last piece.
#include "core/report_error.h"
#include "tasks/checked_tasks.h"
#include "meff/error.h"
#include "meff/task_system.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace meff
{

namespace
{

using Task = FunctionRef<void(int begin, int end, int worker)>;

/// A hint to the core that this thread is spinning (lets a hyper-threaded sibling run).
inline void CpuRelax()
{
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

/// How long a thread spins for the next job or for the end of one before it sleeps: longer
/// than the gap between the solver's jobs in one step, far shorter than a frame.
constexpr std::chrono::microseconds kSpinTime{200};

/// Spins until `done()` or kSpinTime has passed, yielding the core between checks after the
/// first few (the machine may have fewer cores than threads). Returns done().
template <typename Done>
bool SpinUntil(Done&& done)
{
    for (int i = 0; i < 64; ++i)
    {
        if (done())
        {
            return true;
        }
        CpuRelax();
    }
    const auto deadline = std::chrono::steady_clock::now() + kSpinTime;
    while (!done())
    {
        if (std::chrono::steady_clock::now() > deadline)
        {
            return false;
        }
        std::this_thread::yield();
    }
    return true;
}

class ThreadPool final : public TaskSystem
{
  public:
    explicit ThreadPool(int threads) : m_threadCount(threads)
    {
        m_threads.reserve(static_cast<std::size_t>(threads - 1));
        for (int worker = 1; worker < threads; ++worker)
        {
            m_threads.emplace_back([this, worker] { WorkerLoop(worker); });
        }
    }

    ~ThreadPool() override
    {
        {
            const std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_all();
        for (std::thread& thread : m_threads)
        {
            thread.join();
        }
    }

    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int ThreadCount() const override { return m_threadCount; }

    void ParallelFor(int count, int minRange, Task task) override
    {
        if (count <= 0)
        {
            return;
        }
        // About four pieces per thread, so that a thread slowed by the machine leaves its share
        // to the others, but never pieces shorter than the caller asked for.
        const long long pieceGoal = 4LL * m_threadCount;
        const int range =
            std::max({minRange, 1, static_cast<int>((count + pieceGoal - 1) / pieceGoal)});
        const int pieces = static_cast<int>((count + (range - 1LL)) / range);
        if (m_threadCount == 1 || pieces == 1)
        {
            task(0, count, 0);
            return;
        }

        Job job{&task, count, range, pieces};
        std::uint32_t generation = 0;
        {
            const std::lock_guard lock(m_mutex);
            generation = m_generation.load(std::memory_order_relaxed) + 1;
            m_job = job;
            m_unfinished.store(pieces, std::memory_order_relaxed);
            m_generation.store(generation, std::memory_order_relaxed);
            m_cursor.store(std::uint64_t{generation} << 32, std::memory_order_release);
        }
        m_wake.notify_all();

        TakePieces(job, generation, 0);
        const auto finished = [&] { return m_unfinished.load(std::memory_order_acquire) == 0; };
        if (!SpinUntil(finished))
        {
            std::unique_lock lock(m_mutex);
            m_done.wait(lock, finished);
        }
    }

  private:
    struct Job
    {
        const Task* task = nullptr;
        int count = 0, range = 0, pieces = 0;
    };

    /// Runs pieces of job `generation` until none is left to take (or another job began).
    void TakePieces(const Job& job, std::uint32_t generation, int worker)
    {
        std::uint64_t cursor = m_cursor.load(std::memory_order_relaxed);
        for (;;)
        {
            const auto piece = static_cast<std::uint32_t>(cursor);
            if (cursor >> 32 != generation || piece >= static_cast<std::uint32_t>(job.pieces))
            {
                return;
            }
            if (!m_cursor.compare_exchange_weak(cursor, cursor + 1, std::memory_order_acquire,
                                                std::memory_order_relaxed))
            {
                continue; // `cursor` now holds the current value
            }
            const int begin = static_cast<int>(piece) * job.range;
            (*job.task)(begin, std::min(job.count, begin + job.range), worker);
            // Release: the piece's writes are seen by the caller once it sees zero.
            if (m_unfinished.fetch_sub(1, std::memory_order_acq_rel) == 1)
            {
                const std::lock_guard lock(m_mutex); // the caller may be going to sleep
                m_done.notify_one();
            }
            cursor = m_cursor.load(std::memory_order_relaxed);
        }
    }

    void WorkerLoop(int worker)
    {
        std::uint32_t seen = 0;
        for (;;)
        {
            SpinUntil([&] { return m_generation.load(std::memory_order_relaxed) != seen; });
            Job job;
            {
                std::unique_lock lock(m_mutex);
                m_wake.wait(
                    lock,
                    [&] { return m_stop || m_generation.load(std::memory_order_relaxed) != seen; });
                if (m_stop)
                {
                    return;
                }
                seen = m_generation.load(std::memory_order_relaxed);
                job = m_job;
            }
            TakePieces(job, seen, worker);
        }
    }

    const int m_threadCount;
    std::vector<std::thread> m_threads;
    std::mutex m_mutex;
    std::condition_variable m_wake; ///< workers: a new job, or stop
    std::condition_variable m_done; ///< the caller: the job's last piece finished
    Job m_job;                      ///< the current job (guarded by m_mutex)
    /// The current job's number, written under m_mutex; workers spin on it without the lock.
    std::atomic<std::uint32_t> m_generation{0};
    std::atomic<std::uint64_t> m_cursor{0}; ///< (generation << 32) | next piece to take
    std::atomic<int> m_unfinished{0};       ///< the current job's pieces not yet finished
    bool m_stop = false;                    ///< guarded by m_mutex
};

} // namespace

std::unique_ptr<TaskSystem> MakeThreadPool(int threads)
{
    if (threads < 1 || threads > detail::kMaxTaskThreads)
    {
        detail::ReportError(InvalidArgument("MakeThreadPool: threads must be from 1 to " +
                                            std::to_string(detail::kMaxTaskThreads) + ", got " +
                                            std::to_string(threads)));
        return nullptr;
    }
    return std::make_unique<ThreadPool>(threads);
}

} // namespace meff
