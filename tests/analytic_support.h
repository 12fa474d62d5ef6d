// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Helpers shared by the analytic-oracle tests of the World (test_effective_mass.cpp,
// test_collisions.cpp, test_pendulum.cpp, test_ramp.cpp, test_stacking.cpp,
// test_world_analytic.cpp). Every oracle there is a closed form of rigid-body mechanics; the
// expected values are computed in double from the engine's own inputs, and every tolerance is
// derived (in a comment next to it) from float precision, the step size, or a known
// approximation of the Box2D 2.4.1 solver the engine follows.
#pragma once

#include "meff/world.h"

#include <cmath>
#include <limits>

namespace meff::analytic
{

/// Machine epsilon of the engine's scalar: 1.19e-7 for float, 2.2e-16 for double.
inline constexpr double kEps = std::numeric_limits<Real>::epsilon();

/// Relative tolerance for a quantity that the engine computes with a few dozen roundings and no
/// cancellation worth mentioning: 128 ulps (1.5e-5 for float). Used wherever the physics is
/// exact for the solver (one contact point or one joint solved exactly in one step), so that
/// the only error left is floating-point rounding.
inline constexpr double kRoundoff = 128 * kEps;

inline constexpr double kPiD = 3.14159265358979323846;

/// Box2D's testbed rate, the step everything here uses unless it says otherwise.
inline constexpr Real kDt = Real(1.0 / 60.0);

/// A shape definition with the given material, everything else default. (Designated
/// initializers would do, but GCC's -Wextra warns about the members they leave out.)
inline ShapeDef Material(Real density, Real friction, Real restitution = 0)
{
    ShapeDef def;
    def.density = density;
    def.friction = friction;
    def.restitution = restitution;
    return def;
}

/// A world with the given gravity and iteration counts, everything else default but sleeping:
/// the exact answers assume bodies that keep moving (a body slower than 0.01 m/s for 0.5 s
/// would otherwise stop where it is).
inline World MakeWorld(Vec2 gravity, int velocityIterations = 8, int positionIterations = 3)
{
    WorldDef def;
    def.gravity = gravity;
    def.allowSleep = false;
    def.solver.velocityIterations = velocityIterations;
    def.solver.positionIterations = positionIterations;
    return World{def};
}

/// A static body at `position` with no shapes (a joint anchor).
inline BodyId AddAnchor(World& world, Vec2 position)
{
    BodyDef def;
    def.position = position;
    return world.CreateBody(def);
}

inline BodyId AddBox(World& world, BodyType type, Vec2 position, Real angle, Real halfWidth,
                     Real halfHeight, const ShapeDef& material)
{
    BodyDef def;
    def.type = type;
    def.position = position;
    def.angle = angle;
    const BodyId body = world.CreateBody(def);
    world.CreateShape(body, material, MakeBox(halfWidth, halfHeight));
    return body;
}

inline BodyId AddBall(World& world, Vec2 position, Vec2 velocity, Real radius,
                      const ShapeDef& material)
{
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    def.linearVelocity = velocity;
    const BodyId body = world.CreateBody(def);
    world.CreateShape(body, material, Circle{{0, 0}, radius});
    return body;
}

/// Linear momentum of the given bodies (kg·m/s), accumulated in double.
struct Momentum
{
    double x = 0;
    double y = 0;
};

template <typename Range>
Momentum LinearMomentum(const World& world, const Range& bodies)
{
    Momentum p;
    for (const BodyId b : bodies)
    {
        const double m = world.GetMass(b);
        const Vec2 v = world.GetLinearVelocity(b);
        p.x += m * v.x;
        p.y += m * v.y;
    }
    return p;
}

template <typename Range>
double KineticEnergy(const World& world, const Range& bodies)
{
    double e = 0;
    for (const BodyId b : bodies)
    {
        const Vec2 v = world.GetLinearVelocity(b);
        const double w = world.GetAngularVelocity(b);
        e += 0.5 * world.GetMass(b) * (double(v.x) * v.x + double(v.y) * v.y) +
             0.5 * world.GetRotationalInertia(b) * w * w;
    }
    return e;
}

} // namespace meff::analytic
