// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// State shared by the solver stages of one step: body positions and velocities in solver
// order (an island's bodies are contiguous), and the step's constants.
#pragma once

#include "meff/math.h"
#include "meff/settings.h"
#include "meff/task_system.h"

namespace meff::detail
{

// Position and Velocity are aligned to four Reals (16 bytes in float builds), one SSE vector: the
// solvers that work by colour load and store a body's state whole (lane_bodies.h, also with
// eight lanes, which gather two sets of four).

/// Centre of mass and angle of a body during the step.
struct alignas(4 * sizeof(Real)) Position
{
    Vec2 c;
    Real a = 0;
};

/// Linear velocity of the centre of mass and angular velocity during the step.
struct alignas(4 * sizeof(Real)) Velocity
{
    Vec2 v;
    Real w = 0;
};

struct StepContext
{
    Real dt = 0;      ///< s
    Real invDt = 0;   ///< 1/s, 0 when dt is 0
    Real dtRatio = 1; ///< dt / previous dt, scales warm-start impulses
    SolverSettings solver;
    Tolerances tolerances;
};

/// What a joint or contact sees of the step: the constants and the island's state arrays,
/// indexed by each body's solver index.
struct SolverData
{
    StepContext step;
    Position* positions = nullptr;
    Velocity* velocities = nullptr;
    /// A slot after the island's bodies in both arrays, written by SIMD lanes that must not
    /// change their body and never read (lane_bodies.h); −1 where no lanes run. There is one
    /// such slot per worker of `tasks`: worker w's is discardIndex + w.
    std::int32_t discardIndex = -1;
    /// The world's threads (World::SetTaskSystem), for the stages that can use them; null: the
    /// calling thread alone.
    TaskSystem* tasks = nullptr;
};

} // namespace meff::detail
