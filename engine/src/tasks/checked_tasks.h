// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The user's TaskSystem as a world steps on it (World::SetTaskSystem): every range the user's
// job system runs is checked against task_system.h's contract before the engine's task sees it,
// so that a job system that breaks the contract stops the step with an error instead of writing
// outside the engine's per-worker scratch or leaving a job half done unsaid.
#pragma once

#include "meff/task_system.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

namespace meff::detail
{

/// The most threads a world steps on (MakeThreadPool's limit too): the engine sizes per-worker
/// scratch by the thread count.
inline constexpr int kMaxTaskThreads = 1024;

/// Wraps the user's task system for one world. Its thread count is the user's ThreadCount() when
/// the world was given it (from 1 to kMaxTaskThreads, World::SetTaskSystem checks), so scratch
/// sized by it stays right whatever the user's answers later. ParallelFor hands the user's
/// ParallelFor a task that runs the engine's only for a range inside [0, count) with a worker
/// index in [0, ThreadCount()) that no other range is using at that moment, and counts what ran;
/// when the job returns with a range refused or indices run other than once, it reports an error
/// (Error, naming TaskSystem::ParallelFor and what was wrong): thrown, which leaves the step
/// half done and the world frozen; without exceptions, after the error handler the program ends
/// (std::abort): the step can be neither finished nor undone.
class CheckedTasks final : public TaskSystem
{
  public:
    /// `user`: not owned; its ThreadCount() is from 1 to kMaxTaskThreads.
    explicit CheckedTasks(TaskSystem& user);

    /// The user's task system.
    TaskSystem& User() const { return m_user; }
    /// The user's ThreadCount() when it was wrapped.
    int ThreadCount() const override { return m_threadCount; }
    void ParallelFor(int count, int minRange,
                     FunctionRef<void(int begin, int end, int worker)> task) override;

  private:
    /// Records the first range refused in a job (the later ones add nothing to the message).
    void Refuse(const char* what, int begin, int end, int worker);

    TaskSystem& m_user;
    int m_threadCount;
    /// Per worker index: a range is running with it now.
    std::unique_ptr<std::atomic<bool>[]> m_busy;
    /// This job's indices run, and the sum of their indices (each index i adds 2i + 1, so
    /// a range [b, e) adds e² − b²): both are count and count² when every index ran once, and a
    /// range run twice or skipped changes at least one of them (short of an equal and opposite
    /// mistake in the same job).
    std::atomic<std::int64_t> m_ran{0};
    std::atomic<std::uint64_t> m_moment{0};
    std::atomic<bool> m_refused{false};
    std::mutex m_refusalMutex; ///< guards m_refusal, written by the first refused range alone
    std::string m_refusal;
};

} // namespace meff::detail
