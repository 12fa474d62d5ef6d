// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The measures of the soft step's targets (issue 16), each taken the same way for any solver
// back end: the distance of a pendulum from its exact motion, energy drift, joint anchor gaps,
// displacement of resting bodies, penetration beyond rest, and pop-out speed.
#pragma once

#include "meff/analytic.h"
#include "meff/scene.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#ifndef MEFF_SOURCE_DIR
#error "MEFF_SOURCE_DIR must name the repository root"
#endif

namespace meff::soft
{

/// A scene of samples/ (`folder`: "scenes" or "extreme") to be run with `kind`.
inline Scene LoadWith(const std::string& folder, const std::string& name, SolverKind kind)
{
    Scene scene =
        LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/" + folder + "/" + name + ".json");
    scene.world.solver.kind = kind;
    return scene;
}

/// A pendulum set up from a scene's first joint: a dynamic body swinging about a fixed pivot.
struct PendulumRun
{
    double largestDistance = 0; ///< centre of mass from the exact motion, over the run (m)
    double energyChange = 0;    ///< at the end, as a fraction of the swing energy
};

/// Runs `frames` steps of a pendulum scene whose body `bodyIndex` hangs from a static pivot at
/// `pivot`, and compares it with the exact motion. The pendulum's constant k = m·g·d/I_pivot,
/// d the centre of mass's distance from the pivot; `pointMass` when the body turns freely
/// about its centre (a bob on a rigid distance joint): then I_pivot = m·d².
inline PendulumRun RunPendulum(const Scene& scene, std::size_t bodyIndex, Vec2 pivot, int frames,
                               bool pointMass)
{
    BuiltScene built = BuildWorld(scene);
    World& world = built.world;
    const BodyId body = built.bodies.at(bodyIndex);
    const double g = -scene.world.gravity.y;
    const double m = world.GetMass(body);
    const Vec2 c0 = world.GetWorldCenter(body);
    const double dx = double(c0.x) - pivot.x, dy = double(c0.y) - pivot.y;
    const double d = std::hypot(dx, dy);
    const double iPivot = (pointMass ? 0 : double(world.GetRotationalInertia(body))) + m * d * d;
    const double k = m * g * d / iPivot;
    const double psi0 = std::atan2(dx, -dy);
    // RK4 at 2000 steps per frame: below 1e-12 rad of error over 10 s, far below any solver's.
    const analytic::PendulumMotion exact(k, psi0, 0, scene.world.dt, 2000, frames);
    // Energy of the swing: what the drop from the release height to the bottom gives (J).
    const double swing = m * g * (d - d * std::cos(psi0));
    const auto energy = [&]
    {
        const Vec2 v = world.GetLinearVelocity(body);
        const double w = world.GetAngularVelocity(body);
        const double rotational =
            pointMass ? 0 : 0.5 * double(world.GetRotationalInertia(body)) * w * w;
        return 0.5 * m * (double(v.x) * v.x + double(v.y) * v.y) + rotational +
               m * g * double(world.GetWorldCenter(body).y);
    };
    const double e0 = energy();
    PendulumRun run;
    for (int f = 1; f <= frames; ++f)
    {
        world.Step(Real(scene.world.dt));
        const double psi = exact.Angle(std::size_t(f));
        const Vec2 c = world.GetWorldCenter(body);
        const double ex = pivot.x + d * std::sin(psi), ey = pivot.y - d * std::cos(psi);
        run.largestDistance = std::max(run.largestDistance, std::hypot(c.x - ex, c.y - ey));
    }
    run.energyChange = (energy() - e0) / swing;
    return run;
}

/// The distance between each joint's two anchors (m).
inline std::vector<double> AnchorGaps(const BuiltScene& built)
{
    std::vector<double> gaps;
    for (const JointId id : built.joints)
    {
        const Vec2 a = built.world.GetAnchorA(id);
        const Vec2 b = built.world.GetAnchorB(id);
        gaps.push_back(std::hypot(double(a.x) - b.x, double(a.y) - b.y));
    }
    return gaps;
}

/// The deepest contact penetration beyond the resting overlap (m, ≥ 0): two shapes at rest
/// overlap by linearSlop within their skins in every back end, so what counts is beyond it.
inline double PenetrationBeyondRest(const World& world)
{
    const Real slop = world.GetTolerances().linearSlop;
    double deepest = 0;
    for (const ContactPointReport& report : world.GetContactReports())
    {
        deepest = std::max(deepest, -double(report.separation) - slop);
    }
    return deepest;
}

/// The largest distance of any dynamic body's origin from where it started (m).
inline double LargestDisplacement(const BuiltScene& built, const Scene& scene,
                                  const std::vector<Vec2>& start)
{
    double largest = 0;
    for (std::size_t i = 0; i < built.bodies.size(); ++i)
    {
        if (scene.bodies[i].type != BodyType::Dynamic)
        {
            continue;
        }
        const Vec2 p = built.world.GetPosition(built.bodies[i]);
        largest = std::max(largest, std::hypot(double(p.x) - start[i].x, double(p.y) - start[i].y));
    }
    return largest;
}

inline std::vector<Vec2> Positions(const BuiltScene& built)
{
    std::vector<Vec2> positions;
    for (const BodyId id : built.bodies)
    {
        positions.push_back(built.world.GetPosition(id));
    }
    return positions;
}

} // namespace meff::soft
