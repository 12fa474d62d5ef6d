// The contact reports (World::GetContactReports, Box2D 2.4.1's PostSolve data), built when
// they are read. A step only records which contacts it solved and their impulses; the world
// points, normals and separations — a world manifold per contact — are computed on the first
// read, or before anything that would change what they describe (a body moved or destroyed, a
// shape destroyed, a time-of-impact event moving bodies within the step). A game that never
// reads them pays a few bytes per contact per step, as Box2D without a contact listener pays
// nothing.
#pragma once

#include "solvers/solver.h"

#include <span>

namespace meff::detail
{

struct WorldState;
struct SolvedContact;

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
/// (those the step left them at, as long as every change to them calls this first).
void BuildContactReports(WorldState& world);

} // namespace meff::detail
