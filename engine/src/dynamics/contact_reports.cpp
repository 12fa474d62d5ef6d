// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "dynamics/contact_reports.h"

#include "dynamics/events.h"
#include "dynamics/world_state.h"

namespace meff::detail
{

namespace
{

/// Appends the reports of one recorded contact from its geometry.
void AppendReports(const WorldState& world, const SolvedContact& solved,
                   const ContactGeometry& geometry, std::vector<ContactPointReport>& out)
{
    const Contact& contact = world.contacts[solved.contactIndex];
    const Shape& shapeA = world.shapes[contact.shapeA];
    const Shape& shapeB = world.shapes[contact.shapeB];
    const Body& bodyA = world.bodies[contact.bodyA];
    const Body& bodyB = world.bodies[contact.bodyB];
    for (int j = 0; j < solved.pointCount; ++j)
    {
        ContactPointReport report;
        report.bodyA = {contact.bodyA, bodyA.generation};
        report.bodyB = {contact.bodyB, bodyB.generation};
        report.shapeA = {contact.shapeA, shapeA.generation};
        report.shapeB = {contact.shapeB, shapeB.generation};
        report.point = geometry.world.points[j];
        report.normal = geometry.world.normal;
        report.separation = geometry.world.separations[j];
        report.normalImpulse = solved.normalImpulse[j];
        report.tangentImpulse = solved.tangentImpulse[j];
        report.featureKey = geometry.featureKeys[j];
        report.pointIndex = j;
        out.push_back(report);
    }
}

/// A contact's geometry now: its manifold at the bodies' current transforms.
ContactGeometry GeometryOf(const WorldState& world, const Contact& contact)
{
    ContactGeometry geometry;
    geometry.world.Initialize(contact.manifold, world.bodies[contact.bodyA].xf, contact.radiusA,
                              world.bodies[contact.bodyB].xf, contact.radiusB);
    for (int j = 0; j < contact.manifold.pointCount; ++j)
    {
        geometry.featureKeys[j] = contact.manifold.points[j].id.Key();
    }
    return geometry;
}

} // namespace

void RecordedContacts::Clear()
{
    solved.clear();
    discrete = 0;
    eventsBegan = false;
    built.clear();
    lateBuilt = 0;
    if (++round == 0) // wrapped: nothing may look kept in the new round
    {
        std::fill(keptIn.begin(), keptIn.end(), 0U);
        std::fill(bodyKeptIn.begin(), bodyKeptIn.end(), 0U);
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
    auto early = recorded.built.begin(); // solved[discrete, lateBuilt)'s reports, in order
    for (std::size_t i = 0; i < recorded.solved.size(); ++i)
    {
        const SolvedContact& solved = recorded.solved[i];
        const auto c = static_cast<std::size_t>(solved.contactIndex);
        if (i < recorded.discrete && c < recorded.keptIn.size() &&
            recorded.keptIn[c] == recorded.round)
        {
            AppendReports(world, solved, recorded.kept[c], world.contactReports);
            continue;
        }
        if (i >= recorded.discrete && i < recorded.lateBuilt)
        {
            world.contactReports.insert(world.contactReports.end(), early,
                                        early + solved.pointCount);
            early += solved.pointCount;
            continue;
        }
        AppendReports(world, solved, GeometryOf(world, world.contacts[c]), world.contactReports);
    }
    recorded.Clear();
}

void BuildContactReportsOf(WorldState& world, std::int32_t bodyIndex)
{
    RecordedContacts& recorded = world.recorded;
    if (!recorded.eventsBegan)
    {
        recorded.eventsBegan = true;
        recorded.discrete = recorded.solved.size();
        recorded.lateBuilt = recorded.discrete;
        recorded.bodyKeptIn.resize(world.bodies.size());
        recorded.kept.resize(world.contacts.size());
        recorded.keptIn.resize(world.contacts.size());
    }
    // The events' own records, made since the last call: their reports now, before this event.
    for (; recorded.lateBuilt < recorded.solved.size(); ++recorded.lateBuilt)
    {
        const SolvedContact& solved = recorded.solved[recorded.lateBuilt];
        AppendReports(world, solved, GeometryOf(world, world.contacts[solved.contactIndex]),
                      recorded.built);
    }
    const auto b = static_cast<std::size_t>(bodyIndex);
    if (recorded.bodyKeptIn[b] == recorded.round)
    {
        return;
    }
    recorded.bodyKeptIn[b] = recorded.round;
    // The body's touching contacts (those the discrete solve recorded among them) as they are
    // before any event changes them: a contact changes only when one of its bodies is touched.
    // Contacts made during the stage have no discrete record.
    for (std::int32_t key = world.bodies[b].contactList; key != kNullIndex;)
    {
        const auto c = static_cast<std::size_t>(EdgeOwner(key));
        const Contact& contact = world.contacts[c];
        key = contact.edges[EdgeSide(key)].next;
        if (c < recorded.keptIn.size() && recorded.keptIn[c] != recorded.round &&
            contact.IsTouching() && !contact.IsSensor())
        {
            recorded.kept[c] = GeometryOf(world, contact);
            recorded.keptIn[c] = recorded.round;
        }
    }
}

} // namespace meff::detail
