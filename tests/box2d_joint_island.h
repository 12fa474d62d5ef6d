// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A Box2D 2.4.1 island of joints only (no shapes, so no contacts), mirrored body by body and
// joint by joint, and stepped through meff's joint functions by a copy of b2Island::Solve's
// order of operations. Shared by the joint golden tests (test_joints_box2d*.cpp), which step
// Box2D and the mirror side by side and require bit-identical results.
//
// Needs -lbox2d (and /usr/include/box2d).
#pragma once

#ifndef MEFF_DOUBLE

#include "joints/joint.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace meff::test
{

using namespace meff::detail;

inline Vec2 ToMeff(const b2Vec2& v)
{
    return {v.x, v.y};
}

/// Box2D's tuning constants, straight from its macros.
inline Tolerances Box2DTolerances()
{
    Tolerances tol;
    tol.linearSlop = b2_linearSlop;
    tol.angularSlop = b2_angularSlop;
    tol.maxLinearCorrection = b2_maxLinearCorrection;
    tol.maxAngularCorrection = b2_maxAngularCorrection;
    tol.maxTranslation = b2_maxTranslation;
    tol.maxRotation = b2_maxRotation;
    tol.baumgarte = b2_baumgarte;
    return tol;
}

/// One Box2D island mirrored: its bodies in island order and its joints in island order.
struct Island
{
    std::vector<b2Body*> b2Bodies;
    std::vector<JointBody> bodies;
    std::vector<Real> mass, linearDamping, angularDamping;
    std::vector<Position> positions;
    std::vector<Velocity> velocities;
    std::vector<Joint> joints;
    std::vector<b2Joint*> b2Joints;

    /// Adds a body with the data Box2D derives from SetMassData (invI from the inertia about
    /// the centre of mass, m_I = I − m·|c|², in Box2D's float operations).
    std::int32_t Add(b2Body* body, const b2MassData* md)
    {
        JointBody jb;
        jb.solverIndex = static_cast<std::int32_t>(bodies.size());
        jb.localCenter = ToMeff(body->GetLocalCenter());
        Real m = 0;
        if (md != nullptr)
        {
            m = md->mass;
            jb.invMass = 1.0f / md->mass;
            const float centerI = md->I - md->mass * b2Dot(md->center, md->center);
            jb.invI = 1.0f / centerI;
        }
        b2Bodies.push_back(body);
        bodies.push_back(jb);
        mass.push_back(m);
        linearDamping.push_back(body->GetLinearDamping());
        angularDamping.push_back(body->GetAngularDamping());
        Position p;
        p.c = ToMeff(body->GetWorldCenter());
        p.a = body->GetAngle();
        positions.push_back(p);
        Velocity v;
        v.v = ToMeff(body->GetLinearVelocity());
        v.w = body->GetAngularVelocity();
        velocities.push_back(v);
        return jb.solverIndex;
    }
};

/// b2Island::Solve for an island without contacts, in its exact order of operations.
inline void SolveIsland(Island& island, const StepContext& step, Vec2 gravity)
{
    const Real h = step.dt;
    for (std::size_t i = 0; i < island.bodies.size(); ++i)
    {
        if (island.bodies[i].invMass == 0)
        {
            continue; // static: Box2D leaves its (zero) velocity alone
        }
        Vec2 v = island.velocities[i].v;
        Real w = island.velocities[i].w;
        const Vec2 force(0, 0);
        v += h * island.bodies[i].invMass * (Real(1) * island.mass[i] * gravity + force);
        w += h * island.bodies[i].invI * Real(0);
        v *= Real(1) / (Real(1) + h * island.linearDamping[i]);
        w *= Real(1) / (Real(1) + h * island.angularDamping[i]);
        island.velocities[i].v = v;
        island.velocities[i].w = w;
    }

    SolverData data;
    data.step = step;
    data.positions = island.positions.data();
    data.velocities = island.velocities.data();
    for (Joint& j : island.joints)
    {
        if (auto* gear = std::get_if<GearJoint>(&j.data))
        {
            StoreGearBodies(*gear, island.bodies[gear->bodyC], island.bodies[gear->bodyD]);
        }
        InitJointVelocityConstraints(j, island.bodies[j.bodyA], island.bodies[j.bodyB], data);
    }
    for (int i = 0; i < step.solver.velocityIterations; ++i)
    {
        for (Joint& j : island.joints)
        {
            SolveJointVelocityConstraints(j, data);
        }
    }

    const Tolerances& tol = step.tolerances;
    for (std::size_t i = 0; i < island.bodies.size(); ++i)
    {
        Vec2 c = island.positions[i].c;
        Real a = island.positions[i].a;
        Vec2 v = island.velocities[i].v;
        Real w = island.velocities[i].w;
        const Vec2 translation = h * v;
        if (Dot(translation, translation) > tol.maxTranslation * tol.maxTranslation)
        {
            const Real ratio = tol.maxTranslation / translation.Length();
            v *= ratio;
        }
        const Real rotation = h * w;
        if (rotation * rotation > tol.maxRotation * tol.maxRotation)
        {
            const Real ratio = tol.maxRotation / std::abs(rotation);
            w *= ratio;
        }
        c += h * v;
        a += h * w;
        island.positions[i].c = c;
        island.positions[i].a = a;
        island.velocities[i].v = v;
        island.velocities[i].w = w;
    }

    for (int i = 0; i < step.solver.positionIterations; ++i)
    {
        const bool contactsOkay = true; // no contacts: Box2D's min separation stays 0
        bool jointsOkay = true;
        for (Joint& j : island.joints)
        {
            const bool jointOkay = SolveJointPositionConstraints(j, data);
            jointsOkay = jointsOkay && jointOkay;
        }
        if (contactsOkay && jointsOkay)
        {
            break;
        }
    }
}

inline b2Body* MakeDynamic(b2World& world, b2Vec2 position, float angle, b2MassData& md,
                           float linearDamping = 0, float angularDamping = 0)
{
    b2BodyDef bd;
    bd.type = b2_dynamicBody;
    bd.position = position;
    bd.angle = angle;
    bd.linearDamping = linearDamping;
    bd.angularDamping = angularDamping;
    b2Body* body = world.CreateBody(&bd);
    body->SetMassData(&md);
    return body;
}

/// Largest absolute difference seen.
struct Diff
{
    double max = 0;
    void Add(double a, double b) { max = std::max(max, std::abs(a - b)); }
    void Add(Vec2 a, b2Vec2 b)
    {
        Add(a.x, b.x);
        Add(a.y, b.y);
    }
};

/// The StepContext b2World::Step hands to every island for one step of length dt, with the
/// iteration counts given to b2World::Step. invDt0 is b2World's m_inv_dt0 (0 before the first
/// step): it scales the warm-start impulses by dtRatio and is advanced to this step's 1/dt.
inline StepContext Box2DStepContext(float dt, float& invDt0, int velocityIterations,
                                    int positionIterations, bool warmStarting,
                                    const Tolerances& tol)
{
    StepContext step;
    step.dt = dt;
    step.invDt = 1.0f / dt;
    step.dtRatio = invDt0 * dt;
    step.solver.velocityIterations = velocityIterations;
    step.solver.positionIterations = positionIterations;
    step.solver.warmStarting = warmStarting;
    step.solver.blockJoints = true; // Box2D's only mode
    step.tolerances = tol;
    invDt0 = step.invDt;
    return step;
}

/// Solves each mirrored island for one step (after Box2D's world has taken the same step) and
/// accumulates how far every body's position, angle and velocity, and every joint's reaction
/// force and torque, are from Box2D's.
inline void SolveIslandsAndCompare(const std::vector<Island*>& islands, const StepContext& step,
                                   Vec2 gravity, Diff& position, Diff& velocity, Diff& reaction)
{
    for (Island* island : islands)
    {
        SolveIsland(*island, step, gravity);
        for (std::size_t b = 0; b < island->bodies.size(); ++b)
        {
            const b2Body* body = island->b2Bodies[b];
            position.Add(island->positions[b].c, body->GetWorldCenter());
            position.Add(island->positions[b].a, body->GetAngle());
            velocity.Add(island->velocities[b].v, body->GetLinearVelocity());
            velocity.Add(island->velocities[b].w, body->GetAngularVelocity());
        }
        for (std::size_t j = 0; j < island->joints.size(); ++j)
        {
            const JointReaction r = GetJointReaction(island->joints[j], step.invDt);
            reaction.Add(r.force, island->b2Joints[j]->GetReactionForce(step.invDt));
            reaction.Add(r.torque, island->b2Joints[j]->GetReactionTorque(step.invDt));
        }
    }
}

} // namespace meff::test

#endif // MEFF_DOUBLE
