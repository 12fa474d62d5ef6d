// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The error handler (meff/error.h) and the default one, which writes to stderr.
#include "core/report_error.h"

#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace meff
{

namespace
{

struct Handler
{
    std::mutex mutex;
    ErrorHandler function = nullptr;
    void* context = nullptr;
};

Handler& TheHandler()
{
    static Handler handler;
    return handler;
}

} // namespace

void SetErrorHandler(ErrorHandler handler, void* context)
{
    Handler& h = TheHandler();
    const std::scoped_lock lock(h.mutex);
    h.function = handler;
    h.context = context;
}

void detail::CallErrorHandler(const char* message)
{
    Handler& h = TheHandler();
    ErrorHandler function = nullptr;
    void* context = nullptr;
    {
        const std::scoped_lock lock(h.mutex);
        function = h.function;
        context = h.context;
    }
    if (function != nullptr)
    {
        function(message, context);
        return;
    }
    std::fprintf(stderr, "meff: %s\n", message);
}

void detail::AbortAfterError()
{
    std::abort();
}

} // namespace meff
