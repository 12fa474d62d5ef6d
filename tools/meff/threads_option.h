// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `--threads N` of `meff run`, `bench`, `sweep` and `render`: threads lent to the world for its
// steps (World::SetTaskSystem), the same results for any N.
#pragma once

#include "meff/task_system.h"

#include <CLI/CLI.hpp>

#include <memory>

namespace meff::cli
{

/// Adds `--threads N` (1 to 1024, default 1) to `app`, storing N in `threads`.
CLI::Option* AddThreadsOption(CLI::App& app, int& threads, const std::string& what);

/// The thread pool for `--threads N`: null for 1, where the world steps on the calling thread
/// alone, as without the option.
std::unique_ptr<TaskSystem> MakeThreads(int threads);

} // namespace meff::cli
