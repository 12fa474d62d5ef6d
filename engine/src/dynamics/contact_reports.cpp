#include "dynamics/contact_reports.h"

#include "dynamics/events.h"
#include "dynamics/world_state.h"

namespace meff::detail
{

namespace
{

/// Appends the reports of one recorded contact, at the bodies' current transforms.
void AppendReports(const WorldState& world, const SolvedContact& solved,
                   std::vector<ContactPointReport>& out)
{
    const Contact& contact = world.contacts[solved.contactIndex];
    const Shape& shapeA = world.shapes[contact.shapeA];
    const Shape& shapeB = world.shapes[contact.shapeB];
    const Body& bodyA = world.bodies[contact.bodyA];
    const Body& bodyB = world.bodies[contact.bodyB];
    WorldManifold wm;
    wm.Initialize(contact.manifold, bodyA.xf, contact.radiusA, bodyB.xf, contact.radiusB);
    for (int j = 0; j < solved.pointCount; ++j)
    {
        ContactPointReport report;
        report.bodyA = {contact.bodyA, bodyA.generation};
        report.bodyB = {contact.bodyB, bodyB.generation};
        report.shapeA = {contact.shapeA, shapeA.generation};
        report.shapeB = {contact.shapeB, shapeB.generation};
        report.point = wm.points[j];
        report.normal = wm.normal;
        report.separation = wm.separations[j];
        report.normalImpulse = solved.normalImpulse[j];
        report.tangentImpulse = solved.tangentImpulse[j];
        report.featureKey = contact.manifold.points[j].id.Key();
        report.pointIndex = j;
        out.push_back(report);
    }
}

/// Builds recorded contact `i`'s reports now, into RecordedContacts::built.
void BuildEarly(WorldState& world, std::size_t i)
{
    RecordedContacts& recorded = world.recorded;
    if (recorded.builtAt.size() < recorded.solved.size())
    {
        recorded.builtAt.resize(recorded.solved.size(), -1); // only once something is built early
    }
    if (recorded.builtAt[i] < 0)
    {
        recorded.builtAt[i] = static_cast<std::int32_t>(recorded.built.size());
        AppendReports(world, recorded.solved[i], recorded.built);
    }
}

/// Makes the contacts recorded so far findable from their contacts (Contact::recordIndex). A
/// contact recorded twice (not done by any back end today) has its earlier record built now.
void MapRecords(WorldState& world)
{
    RecordedContacts& recorded = world.recorded;
    for (std::size_t i = 0; i < recorded.solved.size(); ++i)
    {
        Contact& contact = world.contacts[recorded.solved[i].contactIndex];
        const auto earlier = static_cast<std::size_t>(contact.recordIndex);
        if (earlier < i && recorded.solved[earlier].contactIndex == recorded.solved[i].contactIndex)
        {
            BuildEarly(world, earlier);
        }
        contact.recordIndex = static_cast<std::int32_t>(i);
    }
    recorded.mapped = recorded.solved.size();
    recorded.lateBuilt = recorded.mapped;
    recorded.mapping = true;
    recorded.bodyBuilt.resize(world.bodies.size());
}

} // namespace

void RecordedContacts::Clear()
{
    solved.clear();
    builtAt.clear();
    built.clear();
    mapped = 0;
    mapping = false;
    lateBuilt = 0;
    if (++round == 0) // wrapped: no body may look built in the new round
    {
        std::fill(bodyBuilt.begin(), bodyBuilt.end(), 0U);
        round = 1;
    }
}

void RecordContactReports(WorldState& world, std::span<const SolvedContact> solved)
{
    RecordedContacts& recorded = world.recorded;
    recorded.solved.insert(recorded.solved.end(), solved.begin(), solved.end());
}

void WorldContactSink::Record(std::span<const SolvedContact> solved, bool anyHitEvents,
                              const StepContext& step)
{
    RecordContactReports(m_world, solved);
    if (anyHitEvents)
    {
        ReportHitEvents(m_world, solved, step);
    }
}

void BuildContactReports(WorldState& world)
{
    RecordedContacts& recorded = world.recorded;
    for (std::size_t i = 0; i < recorded.solved.size(); ++i)
    {
        const std::int32_t at = i < recorded.builtAt.size() ? recorded.builtAt[i] : -1;
        if (at < 0)
        {
            AppendReports(world, recorded.solved[i], world.contactReports);
            continue;
        }
        const auto first = recorded.built.begin() + at;
        world.contactReports.insert(world.contactReports.end(), first,
                                    first + recorded.solved[i].pointCount);
    }
    recorded.Clear();
}

void BuildContactReportsOf(WorldState& world, std::int32_t bodyIndex)
{
    RecordedContacts& recorded = world.recorded;
    if (!recorded.mapping)
    {
        MapRecords(world);
    }
    // Recorded since the mapping (by earlier events): built before any other event.
    for (; recorded.lateBuilt < recorded.solved.size(); ++recorded.lateBuilt)
    {
        BuildEarly(world, recorded.lateBuilt);
    }
    const auto b = static_cast<std::size_t>(bodyIndex);
    if (recorded.bodyBuilt[b] == recorded.round)
    {
        return;
    }
    recorded.bodyBuilt[b] = recorded.round;
    for (std::int32_t key = world.bodies[b].contactList; key != kNullIndex;)
    {
        const std::int32_t c = EdgeOwner(key);
        const Contact& contact = world.contacts[c];
        key = contact.edges[EdgeSide(key)].next;
        const auto i = static_cast<std::size_t>(contact.recordIndex);
        if (i < recorded.mapped && recorded.solved[i].contactIndex == c)
        {
            BuildEarly(world, i);
        }
    }
}

} // namespace meff::detail
