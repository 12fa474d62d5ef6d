// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/shared/island_step.h"

#include "joints/joint_slot.h"
#include "model/body.h"
#include "model/contact.h"
#include "tasks/parallel_ranges.h"

#include <cmath>

namespace meff::detail
{

namespace
{

/// The position pass; true when it converged (Box2D's positionSolved).
bool CorrectPositions(ContactStage& contacts, JointStage& joints, SolverData& data)
{
    for (int i = 0; i < data.step.solver.positionIterations; ++i)
    {
        const bool contactsOkay = contacts.SolvePositions(data);
        const bool jointsOkay = joints.SolvePositions(data);
        if (contactsOkay && jointsOkay)
        {
            return true; // every constraint within tolerance: later sweeps would only add drift
        }
    }
    return false;
}

/// One body's velocity for the step (and its sweep's start set to its pose): semi-implicit
/// Euler v += h·(g + F/m), then the damping ODE dv/dt = −c·v solved implicitly (stable for any
/// c·h). Only dynamic bodies change.
Velocity IntegrateVelocity(Body& body, Vec2 gravity, Real h)
{
    Vec2 v = body.linearVelocity;
    Real w = body.angularVelocity;
    body.sweep.c0 = body.sweep.c;
    body.sweep.a0 = body.sweep.a;
    if (body.type == BodyType::Dynamic)
    {
        v += h * body.invMass * (body.gravityScale * body.mass * gravity + body.force);
        w += h * body.invI * body.torque;
        v *= Real(1) / (Real(1) + h * body.linearDamping);
        w *= Real(1) / (Real(1) + h * body.angularDamping);
    }
    return {v, w};
}

/// Moves one body by h·v, its motion clamped to Tolerances::maxTranslation and maxRotation (a
/// body cannot outrun the broad phase's margins); the clamp also scales its velocity.
void IntegratePosition(Position& position, Velocity& velocity, const StepContext& step)
{
    const Real h = step.dt;
    const Tolerances& tol = step.tolerances;
    Vec2 v = velocity.v;
    Real w = velocity.w;
    const Vec2 translation = h * v;
    if (Dot(translation, translation) > tol.maxTranslation * tol.maxTranslation)
    {
        v *= tol.maxTranslation / translation.Length();
    }
    const Real rotation = h * w;
    if (rotation * rotation > tol.maxRotation * tol.maxRotation)
    {
        w *= tol.maxRotation / std::abs(rotation);
    }
    position = {position.c + h * v, position.a + h * w};
    velocity = {v, w};
}

} // namespace

void SolveIsland(SolverWorld& world, Island& island, const StepContext& step,
                 ContactStage& contacts, JointStage& joints)
{
    const IslandContacts islandContacts{island.contacts, world.contacts, world.bodies,
                                        island.bodies};
    IntegrateVelocities(world, island, step,
                        [&] { contacts.Arrange(islandContacts, island.bodies.size()); });
    SolverData data{step, island.positions.data(), island.velocities.data(),
                    static_cast<std::int32_t>(island.bodies.size()), world.tasks};

    contacts.Prepare(islandContacts, data);
    if (step.solver.warmStarting)
    {
        contacts.WarmStart(data);
    }
    joints.Prepare(island.joints, world.joints, world.bodies, data);

    for (int i = 0; i < step.solver.velocityIterations; ++i)
    {
        joints.SolveVelocities(data);
        contacts.SolveVelocities(data);
    }
    contacts.CollectResults();
    StoreContactImpulses(contacts.SolvedContacts(), world.contacts, world.tasks);
    joints.StoreImpulses();

    IntegratePositions(island, step, world.tasks);
    const bool positionSolved = CorrectPositions(contacts, joints, data);
    FinishBodies(world, island, world.tasks);
    world.solvedContacts.Record(contacts.SolvedContacts(), contacts.AnyHitEvents(), step);
    if (world.allowSleep)
    {
        UpdateSleep(world, island, step, positionSolved);
    }
}

void IntegrateVelocities(SolverWorld& world, Island& island, const StepContext& step,
                         FunctionRef<void()> beside)
{
    const std::size_t count = island.bodies.size();
    // A slot more than the island's bodies for each worker: SolverData::discardIndex.
    const auto discardSlots = static_cast<std::size_t>(WorkerCount(world.tasks));
    island.positions.resize(count + discardSlots);
    island.velocities.resize(count + discardSlots);
    const Real h = step.dt;
    // Each body is its own: any thread may take any range of them.
    ForRangesBeside(world.tasks, static_cast<int>(count), kMinBodiesPerTask, beside,
                    [&](int begin, int end, int)
                    {
                        for (auto i = static_cast<std::size_t>(begin);
                             i < static_cast<std::size_t>(end); ++i)
                        {
                            Body& body = world.bodies[island.bodies[i]];
                            island.positions[i] = {body.sweep.c, body.sweep.a};
                            island.velocities[i] = IntegrateVelocity(body, world.gravity, h);
                        }
                    });
}

void IntegratePositions(Island& island, const StepContext& step, TaskSystem* tasks)
{
    ForEachIndex(tasks, static_cast<int>(island.bodies.size()), kMinBodiesPerTask,
                 [&](int i)
                 {
                     const auto b = static_cast<std::size_t>(i);
                     IntegratePosition(island.positions[b], island.velocities[b], step);
                 });
}

void StoreContactImpulses(std::span<const SolvedContact> solved, std::span<Contact> contacts,
                          TaskSystem* tasks)
{
    // Each solved contact writes only its own contact: any thread may take any range of them
    // (a contact's store costs about what a body's copy does).
    ForEachIndex(tasks, static_cast<int>(solved.size()), kMinBodiesPerTask,
                 [&](int i)
                 {
                     const SolvedContact& s = solved[static_cast<std::size_t>(i)];
                     contacts[s.contactIndex].rollingImpulse = s.rollingImpulse;
                     Manifold& manifold = contacts[s.contactIndex].manifold;
                     for (int j = 0; j < s.pointCount; ++j)
                     {
                         manifold.points[j].normalImpulse = s.normalImpulse[j];
                         manifold.points[j].tangentImpulse = s.tangentImpulse[j];
                     }
                 });
}

} // namespace meff::detail
