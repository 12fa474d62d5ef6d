// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "plot_program.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace meff::cli
{

int RunProgram(const std::vector<std::string>& arguments, bool quiet)
{
    std::vector<char*> argv;
    for (const std::string& argument : arguments)
    {
        argv.push_back(const_cast<char*>(argument.c_str()));
    }
    argv.push_back(nullptr);
    std::fflush(nullptr);
    const pid_t child = fork();
    if (child < 0)
    {
        return -1;
    }
    if (child == 0)
    {
        if (quiet)
        {
            const int null = open("/dev/null", O_WRONLY);
            if (null >= 0)
            {
                dup2(null, STDOUT_FILENO);
                dup2(null, STDERR_FILENO);
            }
        }
        execvp(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    while (waitpid(child, &status, 0) < 0)
    {
        if (errno != EINTR)
        {
            return -1;
        }
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string FindPlottingPython()
{
    std::vector<std::string> candidates;
    if (const char* chosen = std::getenv("MEFF_PYTHON"); chosen != nullptr && *chosen != '\0')
    {
        candidates.emplace_back(chosen);
    }
    candidates.emplace_back("python3");
    candidates.emplace_back("/usr/bin/python3");
    for (const std::string& python : candidates)
    {
        if (RunProgram({python, "-c", "import matplotlib"}, true) == 0)
        {
            return python;
        }
    }
    return {};
}

} // namespace meff::cli
