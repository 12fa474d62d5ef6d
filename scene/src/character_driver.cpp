// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// BuiltScene::Step: the scene's characters (SceneCharacter) moved as a game moves its player,
// then the world's step. A character is a kinematic body: the mover (World::MoveCharacter)
// says where its capsule may go this step, and the body is given the velocity that carries it
// there, so the world's step moves it, dynamic bodies feel it, and every tool (run, render,
// bench, sweep) sees it as one more body.
#include "meff/scene.h"

namespace meff
{

namespace
{

/// The inputs whose time has come by the start of the step at `time` (s). An input a
/// thousandth of a step late still acts on this step, so that "time": 1.5 at 60 Hz is step 90
/// whatever the rounding of 90·dt.
void TakeInputs(BuiltCharacter& character, double time, double dt)
{
    for (; character.nextInput < character.inputs.size(); ++character.nextInput)
    {
        const SceneCharacterInput& input = character.inputs[character.nextInput];
        if (input.time > time + 1e-3 * dt)
        {
            return;
        }
        if (input.walk)
        {
            character.walk = Real(*input.walk);
        }
        if (input.jump)
        {
            character.velocity.y = Real(*input.jump);
        }
    }
}

void DriveCharacter(World& world, BuiltCharacter& character, Real dt)
{
    TakeInputs(character, double(world.GetStepCount()) * double(dt), double(dt));
    // Gravity accelerates it; the player sets its horizontal speed (a walk, not a push).
    character.velocity += (dt * character.gravityScale) * world.GetGravity();
    character.velocity.x = character.walk;
    const Transform xf = world.GetTransform(character.body);
    const Capsule mover{Mul(xf, character.capsule.center1), Mul(xf, character.capsule.center2),
                        character.capsule.radius};
    const CharacterMove move = world.MoveCharacter(mover, character.velocity, dt, character.filter);
    character.velocity = move.velocity;
    // A kinematic body moves by exactly v·dt in the step (it feels no forces), so this carries
    // the capsule to where the mover said, to the step's rounding.
    world.SetLinearVelocity(character.body, (Real(1) / dt) * move.translation);
    world.SetAngularVelocity(character.body, 0);
}

} // namespace

void BuiltScene::Step(Real dt)
{
    for (BuiltCharacter& character : characters)
    {
        DriveCharacter(world, character, dt);
    }
    world.Step(dt);
}

} // namespace meff
