#include "threads_option.h"

#include <string>

namespace meff::cli
{

CLI::Option* AddThreadsOption(CLI::App& app, int& threads, const std::string& what)
{
    return app
        .add_option("--threads", threads,
                    what + " (default 1). For now only the colour back end (--solver colour, "
                           "world.solver \"colour\") uses them, in its contact lanes; the results "
                           "are the same bit for bit for any N")
        ->type_name("N")
        ->check(CLI::Range(1, 1024));
}

std::unique_ptr<TaskSystem> MakeThreads(int threads)
{
    return threads > 1 ? MakeThreadPool(threads) : nullptr;
}

} // namespace meff::cli
