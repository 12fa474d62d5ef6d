// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A game built with -fno-exceptions against an engine built with MEFF_EXCEPTIONS=OFF: a bad
// argument reaches the game's error handler, and the refused call changes nothing.
#include <meff/world.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace
{

/// The game's error hook: here it logs and counts; a game might assert in a debug build.
void OnPhysicsError(const char* message, void* context)
{
    std::fprintf(stderr, "physics error: %s\n", message);
    ++*static_cast<int*>(context);
}

} // namespace

int main()
{
    using namespace meff;
    int errors = 0;
    SetErrorHandler(&OnPhysicsError, &errors);

    World world{WorldDef{.gravity = {0, -10}}};
    const BodyId box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {0, 4}});
    world.CreateShape(box, ShapeDef{.density = 1}, MakeBox(0.5f, 0.5f));

    // A NaN position: refused, reported once, a null id back, no body made.
    const BodyId bad = world.CreateBody(BodyDef{.position = {std::nanf(""), 0}});
    const bool refused = bad.IsNull() && errors == 1 && world.GetBodies().size() == 1;
    // A destroyed body's id: refused, reported, and the read gives a zero vector.
    world.DestroyBody(box);
    const Vec2 stale = world.GetPosition(box);
    const bool staleRefused = errors == 2 && stale.x == 0 && stale.y == 0;
    // The world steps on.
    world.Step(1.0f / 60);

    std::printf("%d errors reported through the hook; the world has %zu bodies\n", errors,
                world.GetBodies().size());
    return refused && staleRefused && errors == 2 ? 0 : 1;
}
