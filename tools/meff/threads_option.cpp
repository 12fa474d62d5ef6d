#include "threads_option.h"

#include <string>

namespace meff::cli
{

CLI::Option* AddThreadsOption(CLI::App& app, int& threads, const std::string& what)
{
    return app
        .add_option("--threads", threads,
                    what + " (default 1). Only the colour back end (--solver colour, "
                           "world.solver \"colour\") uses them: its contact and joint lanes, "
                           "integration and writing the bodies back; the results are the same "
                           "bit for bit for any N")
        ->type_name("N")
        ->check(CLI::Range(1, 1024));
}

std::unique_ptr<TaskSystem> MakeThreads(int threads)
{
    return threads > 1 ? MakeThreadPool(threads) : nullptr;
}

} // namespace meff::cli
