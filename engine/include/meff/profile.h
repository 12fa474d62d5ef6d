// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Where the last World::Step's time went, stage by stage.
#pragma once

namespace meff
{

/// Wall time of the last World::Step's stages, in milliseconds of the steady clock (as Box2D
/// v3's b2Profile): where a step's time goes, for profiling a game or `meff bench --profile`.
/// Timings only: they vary from run to run, are not part of the state hash and do not change
/// the simulation.
struct StepProfile
{
    double step = 0;         ///< ms, the whole step (the sum of the stages below and the rest)
    double findContacts = 0; ///< ms, broad phase: new pairs become contacts (both passes)
    double collide = 0;      ///< ms, narrow phase: every touching contact's manifold
    double solve = 0;        ///< ms, the solver back end: integration, constraints, sleep
    double synchronize = 0;  ///< ms, moving the moved bodies' shapes in the broad phase
    double continuous = 0;   ///< ms, continuous collision (0 when it is off)
};

} // namespace meff
