// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Hello, meff: a box falls onto the ground (the README's first program).
#include <meff/world.h>

#include <cstdio>

int main()
{
    using namespace meff;
    World world{WorldDef{.gravity = {0, -10}}};

    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(20, 1, {0, -1}, 0)); // top at y = 0

    const BodyId box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {0, 4}});
    world.CreateShape(box, ShapeDef{.density = 1, .friction = 0.6f}, MakeBox(0.5f, 0.5f));

    for (int step = 0; step < 90; ++step) // 1.5 s at a fixed 60 Hz
    {
        world.Step(1.0f / 60.0f);
        if (step % 15 == 14)
            std::printf("t = %.2f s  box at y = %.3f m\n", (step + 1) / 60.0,
                        world.GetPosition(box).y);
    }
}
