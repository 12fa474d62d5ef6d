// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Spreading work over cores (--jobs N) and over machines (--shard I/N), the same way for every
// subcommand that offers them: the answers never depend on how the work was spread.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace meff::cli
{

/// `--shard I/N`: this is the I-th (1-based, as GitLab's CI_NODE_INDEX) of N machines.
struct Shard
{
    int index = 1; ///< 1..count
    int count = 1;
};

/// Parses "I/N" with 1 <= I <= N; false when the text is anything else.
bool ParseShard(const std::string& text, Shard& shard);

/// Adds `--shard I/N` to `app`, checked as it is parsed; `what` says what is shared out.
void AddShardOption(CLI::App* app, Shard& shard, const std::string& what);

/// Adds `--jobs N` (1..1024; 0, the default, means one per core) to `app`.
void AddJobsOption(CLI::App* app, int& jobs, const std::string& what);

/// The number of threads to use: `jobs`, or the number of cores when it is 0.
int ResolveJobs(int jobs);

/// The items (by index into `keys`) that belong to `shard`: the items are ranked by their key
/// (byte order, ties by position), and the item of rank r goes to shard r mod N + 1. The same
/// keys give every machine the same shares whatever order its shell listed them in, and
/// together the N shares hold every item exactly once. Returned in the order of `keys`.
std::vector<std::size_t> ShardOf(const std::vector<std::string>& keys, const Shard& shard);

/// Whether item `rank` (already in a fixed order, such as frame numbers) belongs to `shard`.
inline bool InShard(std::size_t rank, const Shard& shard)
{
    return rank % std::size_t(shard.count) == std::size_t(shard.index - 1);
}

/// Runs work(0), ..., work(count - 1) on `jobs` threads and calls finish(i) on the calling
/// thread in index order, each as soon as work(0..i) are all done (so output printed by
/// `finish` is the same whatever `jobs` is). With jobs = 1 everything runs on the calling
/// thread, one item after the other. An exception thrown by work(i) is thrown again from the
/// finish of item i, after the threads have stopped taking new items.
void RunInOrder(std::size_t count, int jobs, const std::function<void(std::size_t)>& work,
                const std::function<void(std::size_t)>& finish);

} // namespace meff::cli
