// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// How the library reports errors: by exception, never by undefined behaviour.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace meff
{

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
