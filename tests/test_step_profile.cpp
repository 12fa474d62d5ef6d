// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// World::GetProfile: the last step's time, stage by stage (issue 17's per-stage profile).
#include <catch2/catch.hpp>

#include "analytic_support.h"
#include "meff/world.h"

using namespace meff;
using namespace meff::analytic;

namespace
{

/// A 10-box stack on the ground, a fast ball aimed at it (continuous collision's work).
World MakeStackWorld(bool continuous)
{
    WorldDef def;
    def.continuous = continuous;
    World world{def};
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(20, 1, {0, -1}, 0));
    for (int i = 0; i < 10; ++i)
    {
        AddBox(world, BodyType::Dynamic, {0, Real(0.5) + Real(i)}, 0, Real(0.5), Real(0.5),
               Material(1, Real(0.6)));
    }
    BodyDef bullet;
    bullet.type = BodyType::Dynamic;
    bullet.position = {-15, 3};
    bullet.linearVelocity = {300, 0};
    bullet.bullet = true;
    world.CreateShape(world.CreateBody(bullet), ShapeDef{.density = 1}, Circle{{0, 0}, Real(0.1)});
    return world;
}

} // namespace

TEST_CASE("The step profile accounts for a step's time stage by stage", "[profile]")
{
    for (const bool continuous : {false, true})
    {
        CAPTURE(continuous);
        World world = MakeStackWorld(continuous);
        const StepProfile before = world.GetProfile();
        CHECK(before.step == 0); // nothing measured before the first step
        for (int i = 0; i < 30; ++i)
        {
            world.Step(kDt);
            const StepProfile& p = world.GetProfile();
            // The stages run inside the step's own timer, one after another, so their times
            // add up to at most the step's (the rest is setup and events). Both are read
            // from the same steady clock, so no tolerance is needed: each stage's interval
            // lies inside the step's.
            const double stages =
                p.findContacts + p.collide + p.solve + p.synchronize + p.continuous;
            CHECK(p.step > 0);
            CHECK(stages <= p.step);
            CHECK(p.collide > 0);
            CHECK(p.solve > 0);
            CHECK(p.findContacts > 0); // the second pass runs every step
            // Continuous collision's time is counted only when it runs.
            CHECK((p.continuous > 0) == continuous);
        }
    }
}

TEST_CASE("Profiling changes nothing the world simulates", "[profile]")
{
    // Two identical worlds stepped alike end in the same state whatever their timings were:
    // the profile is not part of the state (hash) and feeds nothing back.
    World a = MakeStackWorld(true);
    World b = MakeStackWorld(true);
    for (int i = 0; i < 60; ++i)
    {
        a.Step(kDt);
        b.Step(kDt);
        REQUIRE(a.GetStateHash() == b.GetStateHash());
    }
}
