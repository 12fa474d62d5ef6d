// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The named stages of World::Step (step.cpp) and the contact lifecycle (contact_manager.cpp).
#pragma once

#include "model/solver_types.h"

#include <cstdint>

namespace meff::detail
{

struct WorldState;
struct Body;

StepContext BeginStep(WorldState& world, Real dt);
/// Hands the awake bodies to the solver back end SolverSettings::kind chooses
/// (solvers/solver.h).
void Solve(WorldState& world, const StepContext& step);
void SynchronizeShapes(WorldState& world);
/// Moves the broad-phase boxes of one body's shapes to cover its sweep from (c0, a0) to now.
void SynchronizeBodyShapes(WorldState& world, Body& body);
/// Continuous collision (continuous.cpp): Box2D 2.4.1's b2World::SolveTOI. Finds the earliest
/// time of impact among the contacts of fast bodies, moves the pair back to it, re-solves it
/// with its static, kinematic or bullet neighbours over the rest of the step, and repeats.
void SolveContinuous(WorldState& world, const StepContext& step);
void ClearForces(WorldState& world);

// Contact lifecycle
/// Creates contacts for the broad phase's new pairs.
void FindNewContacts(WorldState& world);
/// The narrow phase: re-filters flagged contacts, destroys contacts whose fat boxes no longer
/// overlap, updates the manifolds of the rest and records begin/end events.
void Collide(WorldState& world);
/// Re-evaluates one contact's manifold (a sensor's overlap) at the bodies' current transforms:
/// touching flag, begin/end events, clears Contact::Disabled, then the pre-solve callback may
/// set it again (Box2D's b2Contact::Update).
void UpdateContact(WorldState& world, std::int32_t contactIndex);
void DestroyContact(WorldState& world, std::int32_t contactIndex);
/// Wakes both bodies of every touching contact of `bodyIndex`; with `shapeIndex` set, only
/// of that shape's contacts (a body or shape is about to be destroyed or was moved).
void WakeTouchingBodies(WorldState& world, std::int32_t bodyIndex, std::int32_t shapeIndex = -1);
/// Flags every contact between two bodies for re-filtering (a joint was added or removed).
void FlagContactsForFiltering(WorldState& world, std::int32_t bodyA, std::int32_t bodyB);

} // namespace meff::detail
