// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The contact reports (World::GetContactReports, Box2D 2.4.1's PostSolve data), built when
// they are read. A step only records which contacts it solved and their impulses; the world
// points, normals and separations — a world manifold per contact — are computed on the first
// read, or before anything that would change what they describe (a body moved or destroyed, a
// shape destroyed). A time-of-impact event within the step changes a few bodies and their
// contacts: only the reports it could change are built before it (those of the bodies it
// touches, a ground's included). A game that never reads them pays a few bytes per contact per
// step, and those early reports in steps with impacts; Box2D without a contact listener pays
// nothing.
#pragma once

#include "solvers/shared/contact_constraint.h"
#include "solvers/solver.h"
#include "meff/events.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct WorldState;

/// What a contact's reports read from it: its world manifold and its points' feature keys.
struct ContactGeometry
{
    WorldManifold world;
    std::uint32_t featureKeys[2]{};
};

/// The contacts solved this step whose reports are not built yet, in the reports' order. Before
/// a time-of-impact event, what it could change is kept (BuildContactReportsOf): the geometry
/// of the touched bodies' contacts, and the reports of the events' own records.
struct RecordedContacts
{
    std::vector<SolvedContact> solved;
    /// solved[0, discrete) were recorded before the first event of the step (by the discrete
    /// solve: one record per contact); set by the first BuildContactReportsOf.
    std::size_t discrete = 0;
    bool eventsBegan = false;
    /// The reports of solved[discrete, lateBuilt) (the events' own records), built early, in
    /// order.
    std::vector<ContactPointReport> built;
    std::size_t lateBuilt = 0;
    /// Per contact: its geometry, kept in round `keptIn` (before an event changed it).
    std::vector<ContactGeometry> kept;
    std::vector<std::uint32_t> keptIn;
    std::vector<std::uint32_t> bodyKeptIn; ///< per body: the round its contacts were kept in
    std::uint32_t round = 1;

    void Clear();
};

/// The report stage of an island or a time-of-impact sub-step: records the contacts a solver
/// has just solved.
void RecordContactReports(WorldState& world, std::span<const SolvedContact> solved);

/// The world's end of SolvedContactSink: records the solved contacts for the reports, and
/// turns them into hit events (events.h).
class WorldContactSink final : public SolvedContactSink
{
  public:
    explicit WorldContactSink(WorldState& world) : m_world(world) {}
    void Record(std::span<const SolvedContact> solved, bool anyHitEvents,
                const StepContext& step) override;

  private:
    WorldState& m_world;
};

/// Turns the recorded contacts into ContactPointReports at the bodies' current transforms
/// (those the step left them at, as long as every change to them calls this, or
/// BuildContactReportsOf for the bodies it changes, first).
void BuildContactReports(WorldState& world);

/// Before a time-of-impact event moves body `bodyIndex` or refreshes one of its contacts: keeps
/// the geometry of its touching contacts as it is now (the first time in the step),
/// and builds the reports of every contact recorded since the events began (the events' own,
/// which any later event may change). The other reports are still built when read.
void BuildContactReportsOf(WorldState& world, std::int32_t bodyIndex);

} // namespace meff::detail
