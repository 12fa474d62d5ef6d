// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// What every soft row of one step needs to know: the sub-step, the softness of contacts and
// joints, and the island's bodies.
#pragma once

#include "joints/softness.h"
#include "model/solver_types.h"
#include "solvers/soft_step/soft_bodies.h"
#include "meff/settings.h"

namespace meff::detail
{

/// What the soft rows of one sub-step need to know.
struct SoftStepContext
{
    const StepContext* step = nullptr; ///< the whole step (dt, settings, tolerances)
    int substeps = 1;
    Real h = 0, invH = 0;   ///< sub-step (s) and its inverse
    Softness contact;       ///< between two moving bodies
    Softness staticContact; ///< against a body that cannot move: twice as stiff
    /// The joints' rigid rows while solving: soft, their bias at most maxPushOut; in the
    /// joints' position pass, jointCorrection.
    Softness joint;
    /// The joints' position pass (SoftStepSolver::CorrectJoints): rigid rows whose bias is
    /// what the solving bias could not give (Softness::excess), applied to pseudo-velocities
    /// that move the bodies and are then forgotten.
    Softness jointCorrection;
    Real maxPushOut = 0; ///< m/s
    SoftContactModel contactModel = SoftContactModel::Rigid;
    Real contactCorrection = 0; ///< rigid contacts: fraction of the overlap removed per sub-step
    /// How deep into their skins (m) the normal rows let two shapes close by velocity: the
    /// rows' C is a point's separation plus this. Rigid contacts: 0, so an approach stops where
    /// the shapes touch, as Box2D's velocity rows stop it; the slop is only the position
    /// correction's dead band, not room to sink into (docs/soft-step.md, "Contacts that do
    /// not sag"). Soft contacts: linearSlop (Box2D v3's).
    Real rowSlop = 0;
    bool blockSolver = true;      ///< two-point manifolds' normal rows as one block
    bool frictionInSolve = false; ///< no relax sweeps: friction goes with the biased sweep
    bool halfKick = false;        ///< this sweep belongs to one of the step's two half sub-steps
    bool closing = false;         ///< the closing half kick's sweep: springs act, rigid rows relax
    /// The joints' position pass: only rigid rows (points, lengths, locks, limits) act; springs,
    /// motors and the force-bounded joints (motor, mouse, friction) do not.
    bool correcting = false;
    SoftBodies* bodies = nullptr;
    /// The world's threads (SolverWorld::tasks), or null: the lanes of one colour, the bodies'
    /// integration and the rows' preparation are spread over them (worker w writes the discard
    /// slot bodies->DiscardIndex() + w). GatherSoftBodies made a slot for each of them.
    TaskSystem* tasks = nullptr;

    /// The time this sweep's impulses act over (s): a sub-step, or half of one in the step's
    /// opening and closing half kicks. A row bounded by a force or torque (motors, friction
    /// joints, the mouse) may give at most that × the bound.
    Real KickTime() const { return halfKick ? Real(0.5) * h : h; }
};

} // namespace meff::detail
