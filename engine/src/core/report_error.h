// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The one way the engine reports an error: thrown (MEFF_EXCEPTIONS, the default) or handed to
// the game's error handler (meff/error.h, SetErrorHandler), after which the caller returns
// without changing anything. Every check that can refuse returns false once it has reported, so
// that its callers return too: `if (!RequireX(...)) { return {}; }`.
#pragma once

#include "meff/error.h"

namespace meff
{
struct Refusal;
}

namespace meff::detail
{

/// Passes `message` to the error handler (SetErrorHandler), or writes it to stderr.
void CallErrorHandler(const char* message);
/// std::abort(), after an error that leaves nothing to return (ReportFatalError).
[[noreturn]] void AbortAfterError();

/// Reports `error`: throws it with exceptions, else passes its message to the error handler.
template <typename E>
void ReportError(const E& error)
{
#if MEFF_EXCEPTIONS
    throw error;
#else
    CallErrorHandler(error.what());
#endif
}

/// Reports `error` and returns false, for a check that refuses: `return Refuse(...)`.
template <typename E>
bool Refuse(const E& error)
{
    ReportError(error);
    return false;
}

/// Reports `error`, then ends the program when it cannot be returned from (a moved-from World
/// has no state to hand back): thrown with exceptions; else the handler, then std::abort().
template <typename E>
[[noreturn]] void ReportFatalError(const E& error)
{
    ReportError(error);
    AbortAfterError();
}

/// Reports a refusal of the engine's rules (meff/validity.h) as RefusedArgument("FIELD: REASON")
/// and returns false.
bool ReportRefusal(const Refusal& refusal);

} // namespace meff::detail
