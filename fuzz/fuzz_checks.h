// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// What every fuzz target checks of a refusal, and how it reports a finding.
#pragma once

#include "meff/scene.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace meff::fuzz
{

/// Reports a finding of fuzz target `target` and aborts: abort() is what libFuzzer reports as a
/// crash, with the input saved.
[[noreturn]] inline void Finding(const char* target, const std::string& what)
{
    std::fprintf(stderr, "%s finding: %s\n", target, what.c_str());
    std::abort();
}

/// A refusal must say what is wrong: at least one message, each "SOURCE: ..." with something
/// after the file name (docs/scene-format.md).
inline void CheckRejection(const char* target, const SceneError& error, const std::string& source)
{
    if (error.messages().empty())
    {
        Finding(target, "SceneError without messages");
    }
    for (const std::string& message : error.messages())
    {
        if (message.rfind(source + ": ", 0) != 0 || message.size() <= source.size() + 2)
        {
            Finding(target, "rejection message without the file name: " + message);
        }
    }
}

} // namespace meff::fuzz
