// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// What the documentation's code fragments may take as given (tests/docs/check_docs_code.py
// pastes each fragment into a function after MEFF_DOCS_NAMES or MEFF_DOCS_GAME): the game the
// fragments call, and a world with the bodies and values they name.
#pragma once

#include "meff/debug_draw.h"
#include "meff/mover.h"
#include "meff/task_system.h"
#include "meff/world.h"

#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <vector>

namespace docs
{

/// The game of the fragments: runs 120 frames of 1/60 s; everything else it is handed is
/// accepted and dropped.
struct Game
{
    int frames = 0;
    bool running() { return frames++ < 120; }
    float frameSeconds() const { return 1.0f / 60.0f; }
    void draw(const auto&...) {}
    void touch(const auto&...) {}
    void entered(const auto&...) {}
    void stress(const auto&...) {}
    void playImpactSound(const auto&...) {}
};

/// A dynamic 1 m box at (x, y).
inline meff::BodyId DynamicBox(meff::World& world, meff::Real x, meff::Real y)
{
    const meff::BodyId body =
        world.CreateBody(meff::BodyDef{.type = meff::BodyType::Dynamic, .position = {x, y}});
    world.CreateShape(body, meff::ShapeDef{}, meff::MakeBox(0.5f, 0.5f));
    return body;
}

/// Runs one fragment; an exception is a failure naming the fragment's place in the docs.
inline bool Run(const char* where, void (*fragment)())
{
    try
    {
        fragment();
        return true;
    }
    catch (const std::exception& error)
    {
        std::printf("FAIL: %s: the fragment threw: %s\n", where, error.what());
        return false;
    }
}

} // namespace docs

#define MEFF_DOCS_GAME [[maybe_unused]] docs::Game game;

// The world of the fragments: static ground, ceiling and wall; dynamic bodies spread out so
// that nothing starts overlapping; points, masks and helpers the queries and callbacks name.
#define MEFF_DOCS_NAMES                                                                            \
    MEFF_DOCS_GAME                                                                                 \
    [[maybe_unused]] meff::World world{meff::WorldDef{}};                                          \
    [[maybe_unused]] const meff::BodyId ground = world.CreateBody(meff::BodyDef{});                \
    world.CreateShape(ground, meff::ShapeDef{}, meff::MakeOffsetBox(50, 1, {0, -1}, 0));           \
    [[maybe_unused]] const meff::BodyId ceiling =                                                  \
        world.CreateBody(meff::BodyDef{.position = {0, 20}});                                      \
    [[maybe_unused]] const meff::BodyId wall =                                                     \
        world.CreateBody(meff::BodyDef{.position = {-30, 5}});                                     \
    [[maybe_unused]] const meff::BodyId door = docs::DynamicBox(world, 2, 2);                      \
    [[maybe_unused]] const meff::BodyId lamp = docs::DynamicBox(world, 0, 3);                      \
    [[maybe_unused]] const meff::BodyId platform = docs::DynamicBox(world, 6, 1);                  \
    [[maybe_unused]] const meff::BodyId chassis = docs::DynamicBox(world, 10, 2);                  \
    [[maybe_unused]] const meff::BodyId wheel = docs::DynamicBox(world, 10, 0.5f);                 \
    [[maybe_unused]] const meff::BodyId plank = docs::DynamicBox(world, -28, 5);                   \
    [[maybe_unused]] const meff::BodyId carrier = docs::DynamicBox(world, 14, 1);                  \
    [[maybe_unused]] const meff::BodyId box = docs::DynamicBox(world, 18, 1);                      \
    [[maybe_unused]] const meff::BodyId player = docs::DynamicBox(world, 22, 1);                   \
    [[maybe_unused]] const meff::BodyId crate = docs::DynamicBox(world, 26, 1);                    \
    [[maybe_unused]] const meff::ShapeId platformTopShape =                                        \
        world.CreateShape(ground, meff::ShapeDef{}, meff::MakeOffsetBox(2, 0.1f, {-10, 3}, 0));    \
    [[maybe_unused]] const meff::Real platformTop = 3.1f;                                          \
    [[maybe_unused]] const std::vector<meff::Vec2> bowlCorners{                                    \
        {-40, 10}, {-34, 10}, {-34, 4}, {-40, 4}};                                                 \
    [[maybe_unused]] const meff::Vec2 click{18, 1}, pointer{19, 2}, cursor{0, 3}, start{0, 10};    \
    [[maybe_unused]] const meff::Vec2 eye{-5, 1}, target{30, 1};                                   \
    [[maybe_unused]] const std::uint32_t kSolid = 0x0001;                                          \
    [[maybe_unused]] auto isGlass = [](meff::ShapeId) { return false; };                           \
    [[maybe_unused]] auto sameTeam = [](meff::ShapeId, meff::ShapeId) { return false; };           \
    [[maybe_unused]] std::vector<meff::ShapeId> found;                                             \
    [[maybe_unused]] meff::ShapeId picked{};
