// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Using meff inside a game: build a world in code, step it at a fixed rate from a variable-rate
// frame loop, and read back positions and contact impulses. Copy this and change it.
#include "meff/world.h"

#include <cstdio>

int main()
{
    meff::World world(meff::WorldDef{}); // gravity (0, -10) m/s², Box2D's solver settings

    // Ground: a static box whose top face is at y = 0.
    const meff::BodyId ground = world.CreateBody(meff::BodyDef{});
    world.CreateShape(ground, meff::ShapeDef{}, meff::MakeOffsetBox(20, 1, {0, -1}, 0));

    // A crate dropped from 4 m, and a ball rolled at it along the ground.
    meff::BodyDef crateDef;
    crateDef.type = meff::BodyType::Dynamic;
    crateDef.position = {0, 4};
    const meff::BodyId crate = world.CreateBody(crateDef);
    world.CreateShape(crate, meff::ShapeDef{}, meff::MakeBox(0.5f, 0.5f));

    meff::BodyDef ballDef;
    ballDef.type = meff::BodyType::Dynamic;
    ballDef.position = {-6, 0.25f};
    ballDef.linearVelocity = {5, 0};
    const meff::BodyId ball = world.CreateBody(ballDef);
    meff::ShapeDef rubber;
    rubber.restitution = 0.5f;
    world.CreateShape(ball, rubber, meff::Circle{{0, 0}, 0.25f});

    auto name = [&](meff::BodyId id) {
        return id == ground ? "ground" : id == crate ? "crate" : "ball";
    };

    // The game renders at whatever rate it gets; physics always advances in steps of exactly
    // 1/60 s, which keeps it stable and reproducible. Here the "render frames" alternate
    // between 1/50 s and 1/90 s to show the accumulator at work.
    const meff::Real physicsStep = meff::Real(1) / 60;
    meff::Real accumulator = 0;
    double elapsed = 0;
    for (int renderFrame = 0; elapsed < 2.5; ++renderFrame)
    {
        const meff::Real frameTime = renderFrame % 2 == 0 ? meff::Real(1) / 50 : meff::Real(1) / 90;
        elapsed += frameTime;
        accumulator += frameTime;
        while (accumulator >= physicsStep)
        {
            world.Step(physicsStep);
            accumulator -= physicsStep;

            // Contact impulses are those of the step just taken (N·s); divide by the step
            // for a force. Resting contacts carry about m·g·dt; a much larger one is a hit:
            // play a sound, spawn dust, ...
            for (const meff::ContactPointReport& contact : world.GetContactReports())
            {
                if (contact.normalImpulse > 0.2f)
                {
                    std::printf("  t=%.3f s: %s hit %s, impulse %.3f N·s at (%.2f, %.2f)\n",
                                double(world.GetStepCount() * physicsStep), name(contact.bodyB),
                                name(contact.bodyA), double(contact.normalImpulse),
                                double(contact.point.x), double(contact.point.y));
                }
            }
        }

        // Draw here. This example prints every 30th frame instead.
        if (renderFrame % 30 == 0)
        {
            const meff::Vec2 cratePosition = world.GetPosition(crate);
            const meff::Vec2 ballPosition = world.GetPosition(ball);
            std::printf("t=%.2f s  crate (%.3f, %.3f) angle %.3f  ball (%.3f, %.3f)\n", elapsed,
                        double(cratePosition.x), double(cratePosition.y),
                        double(world.GetAngle(crate)), double(ballPosition.x),
                        double(ballPosition.y));
        }
    }
    return 0;
}
