// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "threads_option.h"

#include <string>

namespace meff::cli
{

CLI::Option* AddThreadsOption(CLI::App& app, int& threads, const std::string& what)
{
    return app
        .add_option("--threads", threads,
                    what + " (default 1). The colour and soft step back ends use them for "
                           "the narrow phase's manifolds, the broad phase's boxes and pairs, "
                           "their contact and joint lanes, integration and writing the bodies "
                           "back (box2d steps on one); the results are the same bit for bit "
                           "for any N")
        ->type_name("N")
        ->check(CLI::Range(1, 1024));
}

std::unique_ptr<TaskSystem> MakeThreads(int threads)
{
    return threads > 1 ? MakeThreadPool(threads) : nullptr;
}

} // namespace meff::cli
