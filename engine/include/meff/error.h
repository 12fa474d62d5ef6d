// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// How the library reports errors: by exception (the default), or, in an engine built with
// MEFF_EXCEPTIONS=OFF (-fno-exceptions), through an error handler the game sets; never by
// undefined behaviour.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#ifndef MEFF_EXCEPTIONS
/// 1 when the engine reports errors by throwing them (CMake option MEFF_EXCEPTIONS, the
/// default); 0 in an engine built with MEFF_EXCEPTIONS=OFF, whose usage requirements (the CMake
/// package, meff.pc) define it so.
#define MEFF_EXCEPTIONS 1
#endif

namespace meff
{

/// A function the engine calls with the message of each error it reports when it is built
/// without exceptions (MEFF_EXCEPTIONS=OFF): the same text an exception's what() would carry,
/// "BodyDef::position: must be finite, got (nan, 0)". `context` is the
/// pointer given to SetErrorHandler. The call that reported the error then returns without
/// changing anything: a null id, zero, an empty result. The handler may be called from any
/// thread that calls into the engine (and from the task system's threads for an error found
/// inside World::Step); it must not call back into the world that reported the error.
using ErrorHandler = void (*)(const char* message, void* context);

/// Sets the function that receives the engine's errors when it is built without exceptions,
/// and the context pointer passed to it (nullptr handler: the default, which writes
/// "meff: MESSAGE" to stderr). With exceptions (the default build) errors are thrown as the
/// classes below and the handler is not called. Thread-safe; the handler is global.
void SetErrorHandler(ErrorHandler handler, void* context = nullptr);

/// Base class of every error meff throws.
class Error : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

/// A library call was given an argument it cannot accept (NaN, negative mass, a degenerate
/// polygon, a stale id, ...). The world is unchanged.
class InvalidArgument : public Error
{
  public:
    using Error::Error;
};

/// A step produced a non-finite value. The world keeps the state it had when the step was
/// detected to be bad and stays readable; stepping it again is refused.
class SimulationError : public Error
{
  public:
    /// The message, the failed step and the body's index.
    SimulationError(const std::string& what, std::uint64_t step_, std::int32_t bodyIndex_)
        : Error(what), step(step_), bodyIndex(bodyIndex_)
    {
    }
    std::uint64_t step;     ///< index of the step that failed (0 = the first step)
    std::int32_t bodyIndex; ///< BodyId::index of the body whose state went non-finite
};

} // namespace meff
