// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Sensor events, the pre-solve callback and contact hit events. None of them changes what the
// solver computes: sensor contacts never reach it, hit events only read what it already knew,
// and the pre-solve callback can only take a contact out, as Box2D 2.4.1's SetEnabled(false).
#include "dynamics/events.h"

#include "dynamics/world_state.h"

#include <cstddef>

namespace meff::detail
{

namespace
{

ShapeId ShapeIdOf(const WorldState& world, std::int32_t shape)
{
    return {shape, world.shapes[shape].generation};
}

ContactEvent MakeContactEvent(const WorldState& world, const Contact& contact)
{
    return {ShapeIdOf(world, contact.shapeA), ShapeIdOf(world, contact.shapeB)};
}

/// The sensor is shape A when A is a sensor (also when both are), else shape B.
SensorEvent MakeSensorEvent(const WorldState& world, const Contact& contact)
{
    const bool sensorIsA = world.shapes[contact.shapeA].def.isSensor;
    const std::int32_t sensor = sensorIsA ? contact.shapeA : contact.shapeB;
    const std::int32_t visitor = sensorIsA ? contact.shapeB : contact.shapeA;
    return {ShapeIdOf(world, sensor), ShapeIdOf(world, visitor)};
}

} // namespace

void ClearEvents(WorldState& world)
{
    world.contactReports.clear();
    world.recorded.Clear();
    world.beginEvents.clear();
    world.sensorBeginEvents.clear();
    world.hitEvents.clear();
    world.endEvents.erase(world.endEvents.begin(),
                          world.endEvents.begin() + std::ptrdiff_t(world.stepEndEventCount));
    world.sensorEndEvents.erase(world.sensorEndEvents.begin(),
                                world.sensorEndEvents.begin() +
                                    std::ptrdiff_t(world.stepSensorEndEventCount));
}

void MarkStepEvents(WorldState& world)
{
    world.stepEndEventCount = world.endEvents.size();
    world.stepSensorEndEventCount = world.sensorEndEvents.size();
}

void RecordTouchBegan(WorldState& world, const Contact& contact)
{
    if (contact.IsSensor())
    {
        world.sensorBeginEvents.push_back(MakeSensorEvent(world, contact));
    }
    else
    {
        world.beginEvents.push_back(MakeContactEvent(world, contact));
    }
}

void RecordTouchEnded(WorldState& world, const Contact& contact)
{
    if (contact.IsSensor())
    {
        world.sensorEndEvents.push_back(MakeSensorEvent(world, contact));
    }
    else
    {
        world.endEvents.push_back(MakeContactEvent(world, contact));
    }
}

void RunPreSolve(WorldState& world, std::int32_t contactIndex)
{
    if (!world.preSolve)
    {
        return;
    }
    Contact& contact = world.contacts[contactIndex];
    const Body& bodyA = world.bodies[contact.bodyA];
    const Body& bodyB = world.bodies[contact.bodyB];

    PreSolveContact info;
    info.shapeA = ShapeIdOf(world, contact.shapeA);
    info.shapeB = ShapeIdOf(world, contact.shapeB);
    info.bodyA = {contact.bodyA, bodyA.generation};
    info.bodyB = {contact.bodyB, bodyB.generation};
    info.manifold = &contact.manifold;
    info.worldManifold.Initialize(contact.manifold, bodyA.xf, contact.radiusA, bodyB.xf,
                                  contact.radiusB);
    const InUserCallback inside(world, "the pre-solve callback");
    if (!world.preSolve(info))
    {
        contact.flags |= Contact::Disabled;
    }
}

void ReportHitEvents(WorldState& world, std::span<const SolvedContact> solvedContacts,
                     const StepContext& step)
{
    const Real threshold = step.tolerances.hitEventThreshold;
    // Marks the contacts that already have an event in this step (stepCount advances after it).
    const std::uint64_t stamp = world.stepCount + 1;
    for (const SolvedContact& solved : solvedContacts)
    {
        Contact& contact = world.contacts[solved.contactIndex];
        if ((contact.flags & Contact::HitEvents) == 0)
        {
            continue;
        }
        // The fastest approaching point; a point whose accumulated normal impulse ends at 0
        // did not collide (it was already separating when the solver reached it). Box2D v3
        // tests the largest impulse over the iterations instead, so a point pushed and then
        // fully relaxed counts there and not here.
        int fastest = -1;
        Real fastestSpeed = threshold;
        for (int j = 0; j < solved.pointCount; ++j)
        {
            const Real approachSpeed = -solved.normalVelocity[j];
            if (approachSpeed > fastestSpeed && solved.normalImpulse[j] > 0)
            {
                fastest = j;
                fastestSpeed = approachSpeed;
            }
        }
        if (fastest < 0)
        {
            continue;
        }
        const bool seen = contact.hitStep == stamp;
        if (seen && world.hitEvents[contact.hitEvent].approachSpeed >= fastestSpeed)
        {
            continue; // an earlier sub-step of this step saw this contact hit harder
        }

        WorldManifold wm;
        wm.Initialize(contact.manifold, world.bodies[contact.bodyA].xf, contact.radiusA,
                      world.bodies[contact.bodyB].xf, contact.radiusB);
        const ContactHitEvent event{ShapeIdOf(world, contact.shapeA),
                                    ShapeIdOf(world, contact.shapeB), wm.points[fastest], wm.normal,
                                    fastestSpeed};
        if (seen)
        {
            world.hitEvents[contact.hitEvent] = event;
        }
        else
        {
            contact.hitStep = stamp;
            contact.hitEvent = static_cast<std::int32_t>(world.hitEvents.size());
            world.hitEvents.push_back(event);
        }
    }
}

} // namespace meff::detail
