// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A game's use of meff, built from outside the repository (scripts/check-consumers.sh): a ball
// dropped from 5 m onto the ground, stepped with meff's thread pool (which links the threads
// library). Exit status 0 when it lands where physics says it must.
#include <meff/task_system.h>
#include <meff/world.h>

#include <cmath>
#include <cstdio>
#include <memory>

int main()
{
    using namespace meff;
    World world(WorldDef{});
    const std::unique_ptr<TaskSystem> threads = MakeThreadPool(2);
    world.SetTaskSystem(threads.get());
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(10, 1, {0, -1}, 0));
    BodyDef ballDef;
    ballDef.type = BodyType::Dynamic;
    ballDef.position = {0, 5};
    const BodyId ball = world.CreateBody(ballDef);
    world.CreateShape(ball, ShapeDef{}, Circle{{0, 0}, 0.5f});
    for (int step = 0; step < 180; ++step)
    {
        world.Step(1.0f / 60.0f);
    }
    // At rest on the ground after 3 s: its centre one radius up, less the contact slop the
    // solver leaves (0.005 m) — 1 cm either way is plenty for a check that it landed at all.
    const float y = world.GetPosition(ball).y;
    std::printf("ball at y = %.4f m after 3 s\n", y);
    return std::abs(y - 0.5f) < 0.01f ? 0 : 1;
}
