#include "dynamics/contact_reports.h"

#include "dynamics/events.h"
#include "dynamics/world_state.h"

namespace meff::detail
{

void RecordContactReports(WorldState& world, std::span<const SolvedContact> solved)
{
    world.solvedContacts.insert(world.solvedContacts.end(), solved.begin(), solved.end());
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
    for (const SolvedContact& solved : world.solvedContacts)
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
            world.contactReports.push_back(report);
        }
    }
    world.solvedContacts.clear();
}

} // namespace meff::detail
