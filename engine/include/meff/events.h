// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// What the last World::Step reports: contact points with their impulses, contact begin/end,
// sensor and hit events.
#pragma once

#include "meff/ids.h"
#include "meff/math.h"

#include <cstdint>

namespace meff
{

/// One contact point after a step: Box2D's PostSolve data plus where the point is.
struct ContactPointReport
{
    BodyId bodyA{};               ///< shapeA's body
    BodyId bodyB{};               ///< shapeB's body
    ShapeId shapeA{};             ///< the contact's first shape
    ShapeId shapeB{};             ///< the contact's second shape
    Vec2 point{};                 ///< world point midway between the surfaces (m)
    Vec2 normal{};                ///< unit normal from A to B
    Real separation = 0;          ///< m, negative when overlapping
    Real normalImpulse = 0;       ///< accumulated over the step's velocity iterations (N·s)
    Real tangentImpulse = 0;      ///< friction impulse along the tangent cross(normal, 1) (N·s)
    std::uint32_t featureKey = 0; ///< ContactFeature::Key(), the point's identity
    int pointIndex = 0;           ///< 0 or 1 within its manifold
};

/// Two shapes started or stopped touching during the last step.
struct ContactEvent
{
    ShapeId shapeA{}; ///< the contact's first shape
    ShapeId shapeB{}; ///< the contact's second shape
};

/// A shape started or stopped overlapping a sensor during the last step. When both shapes are
/// sensors, the event is reported once, with the contact's first shape as `sensorShape`.
struct SensorEvent
{
    ShapeId sensorShape{};  ///< the sensor
    ShapeId visitorShape{}; ///< the shape that entered or left it
};

/// A contact that hit faster than Tolerances::hitEventThreshold in the last step (Box2D v3's
/// b2ContactHitEvent): its fastest point, measured before the solver's impulses.
struct ContactHitEvent
{
    ShapeId shapeA{};       ///< the contact's first shape
    ShapeId shapeB{};       ///< the contact's second shape
    Vec2 point{};           ///< world point of the fastest approaching point, after the step (m)
    Vec2 normal{};          ///< unit normal from A to B
    Real approachSpeed = 0; ///< −(relative normal velocity) before impulses (m/s), > threshold
};

} // namespace meff
