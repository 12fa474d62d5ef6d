// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <numeric>
#include <thread>

namespace meff::cli
{

bool ParseShard(const std::string& text, Shard& shard)
{
    int index = 0, count = 0;
    char slash = 0, rest = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &index, &slash, &count, &rest) != 3 || slash != '/' ||
        count < 1 || index < 1 || index > count)
    {
        return false;
    }
    shard = {index, count};
    return true;
}

void AddShardOption(CLI::App* app, Shard& shard, const std::string& what)
{
    app->add_option_function<std::string>(
           "--shard",
           [&shard](const std::string& text)
           {
               if (!ParseShard(text, shard))
               {
                   throw CLI::ValidationError("--shard",
                                              "must be I/N with 1 <= I <= N, got " + text);
               }
           },
           "Take only the I-th of N deterministic shares of the " + what +
               " (1 <= I <= N), so that N machines cover each exactly once")
        ->type_name("I/N");
}

void AddJobsOption(CLI::App* app, int& jobs, const std::string& what)
{
    app->add_option("--jobs,-j", jobs,
                    what + " on N threads at once (default: one per core); the results are "
                           "the same for every N")
        ->type_name("N")
        ->check(CLI::Range(1, 1024));
}

int ResolveJobs(int jobs)
{
    if (jobs > 0)
    {
        return jobs;
    }
    return std::max(1, int(std::thread::hardware_concurrency()));
}

std::vector<std::size_t> ShardOf(const std::vector<std::string>& keys, const Shard& shard)
{
    std::vector<std::size_t> order(keys.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
    std::vector<std::size_t> mine;
    for (std::size_t rank = 0; rank < order.size(); ++rank)
    {
        if (InShard(rank, shard))
        {
            mine.push_back(order[rank]);
        }
    }
    std::sort(mine.begin(), mine.end());
    return mine;
}

void RunInOrder(std::size_t count, int jobs, const std::function<void(std::size_t)>& work,
                const std::function<void(std::size_t)>& finish)
{
    if (jobs <= 1 || count <= 1)
    {
        for (std::size_t i = 0; i < count; ++i)
        {
            work(i);
            finish(i);
        }
        return;
    }
    std::mutex mutex;
    std::condition_variable doneChanged;
    std::vector<char> done(count, 0);
    std::vector<std::exception_ptr> errors(count);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    const auto worker = [&]
    {
        for (;;)
        {
            const std::size_t i = next.fetch_add(1);
            if (i >= count || stop.load())
            {
                return;
            }
            std::exception_ptr error;
            try
            {
                work(i);
            }
            catch (...)
            {
                error = std::current_exception();
            }
            {
                const std::lock_guard lock(mutex);
                errors[i] = error;
                done[i] = 1;
            }
            doneChanged.notify_all();
        }
    };
    std::vector<std::thread> threads;
    const std::size_t threadCount = std::min(std::size_t(jobs), count);
    for (std::size_t t = 0; t < threadCount; ++t)
    {
        threads.emplace_back(worker);
    }
    const auto joinAll = [&]
    {
        stop.store(true);
        for (std::thread& thread : threads)
        {
            thread.join();
        }
    };
    try
    {
        for (std::size_t i = 0; i < count; ++i)
        {
            std::exception_ptr error;
            {
                std::unique_lock lock(mutex);
                doneChanged.wait(lock, [&] { return done[i] != 0; });
                error = errors[i];
            }
            if (error)
            {
                std::rethrow_exception(error);
            }
            finish(i);
        }
    }
    catch (...)
    {
        joinAll();
        throw;
    }
    joinAll();
}

} // namespace meff::cli
