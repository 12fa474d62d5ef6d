// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Game events of a step beyond the contact reports: which list a contact's begin/end goes to
// (sensor or contact events), the pre-solve callback, and contact hit events.
#pragma once

#include "model/solver_types.h"

#include <cstdint>
#include <span>

namespace meff::detail
{

struct WorldState;
struct Contact;
struct SolvedContact;

/// Empties the event lists of the last step (World::Step's first stage). End events recorded
/// after that step ended — a touching shape or body destroyed between steps — are kept, at the
/// front of this step's lists, so a game that reads events once per step still sees them.
void ClearEvents(WorldState& world);
/// Marks where this step's end events stop (World::Step's last stage), for ClearEvents.
void MarkStepEvents(WorldState& world);
/// A contact started touching: a sensor event when it is a sensor contact, else a contact event.
void RecordTouchBegan(WorldState& world, const Contact& contact);
/// A touching contact stopped touching or was destroyed.
void RecordTouchEnded(WorldState& world, const Contact& contact);
/// Box2D 2.4.1's PreSolve, called by UpdateContact for a touching, non-sensor contact: asks the
/// user's callback, if any, and disables the contact for this step when it says no.
void RunPreSolve(WorldState& world, std::int32_t contactIndex);
/// Hit events of contacts a solver has just solved (an island, or a time-of-impact sub-step):
/// for each contact with Contact::HitEvents, its fastest point whose approach speed
/// before impulses exceeds the threshold and which took an impulse. One event per contact per
/// step: a later, faster hit of the same contact in the same step replaces the earlier one.
void ReportHitEvents(WorldState& world, std::span<const SolvedContact> solved,
                     const StepContext& step);

} // namespace meff::detail
