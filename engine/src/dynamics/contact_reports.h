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

#include "solvers/box2d/contact_constraint.h"
#include "solvers/solver.h"
#include "meff/world.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct WorldState;

/// The contacts solved this step whose reports are not built yet, in the reports' order; some
/// may have theirs built early (BuildContactReportsOf).
struct RecordedContacts
{
    std::vector<SolvedContact> solved;
    /// Per solved: its first report in `built`, or -1; shorter than `solved` (the rest -1)
    /// until a report is built early.
    std::vector<std::int32_t> builtAt;
    std::vector<ContactPointReport> built; ///< reports built early
    std::size_t mapped = 0;                ///< solved[0, mapped) found by Contact::recordIndex
    bool mapping = false;                  ///< `mapped` is set (since the last build)
    std::size_t lateBuilt = 0;             ///< solved[mapped, lateBuilt) are built early
    std::vector<std::uint32_t> bodyBuilt;  ///< per body: the round its reports were built in
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

/// Before a time-of-impact event moves body `bodyIndex` or refreshes one of its contacts: builds
/// now, and keeps in place, the reports of its recorded contacts, and of every contact recorded
/// since the first call (the events' own, which any later event may change). The others are
/// still built when read.
void BuildContactReportsOf(WorldState& world, std::int32_t bodyIndex);

} // namespace meff::detail
