// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A small tour of what a game needs from meff, one feature per file. Each stop builds its own
// world, runs it and returns what a game would observe, so the tests in
// test_tour.cpp can hold every stop to its promise and `meff_tour` can print it.
#pragma once

#include "meff/world.h"

#include <cstdint>
#include <cstdio>
#include <vector>

namespace meff::tour
{

/// A box thrown up through a one-way platform (a pre-solve hook disables the contact while the
/// box is below the platform's top), which then lands on it and rests there.
struct OneWayPlatformResult
{
    Real platformTop = 0;        ///< m
    Real highestY = 0;           ///< highest point the box's bottom reached (m)
    Real finalBottomY = 0;       ///< the box's bottom after it settled (m)
    Real finalSpeed = 0;         ///< m/s
    int stepsBelowTopRising = 0; ///< steps the box spent passing up through the platform
};
OneWayPlatformResult RunOneWayPlatform(std::FILE* log = nullptr);

/// A laser in a walled room: the closest hit, the closest hit when a filter looks through
/// glass, every hit along the same ray, and a sweep of rays around the room.
struct RayCastResult
{
    Vec2 closestWithGlass{};       ///< first hit of the ray (m): the glass pane's face
    Vec2 closestThroughGlass{};    ///< first hit when glass is filtered out (m): the ball
    int hitsWithGlass = 0;         ///< every shape along the ray
    int hitsThroughGlass = 0;      ///< the same, glass skipped by the callback
    std::vector<Vec2> sweepPoints; ///< closest hit of each ray of the sweep (m)
    int sweepRays = 0;
};
RayCastResult RunRayCast(std::FILE* log = nullptr);

/// A car on two wheel joints (spring suspension, rear-wheel motor) driving over a bump.
struct CarResult
{
    Real restSag = 0;        ///< chassis drop on its springs once settled (m)
    Real expectedSag = 0;    ///< the springs' static deflection m·g/k from the joint's hertz (m)
    Real distance = 0;       ///< how far the chassis travelled with the motor on (m)
    Real lowestChassisY = 0; ///< m
    Real largestTilt = 0;    ///< |chassis angle| at worst (rad)
};
CarResult RunCar(std::FILE* log = nullptr);

/// Rollback netcode: save the world, play on, restore, and replay the same inputs.
struct RollbackResult
{
    int replayedSteps = 0;
    bool replayMatches = false;         ///< state hash equal at every replayed step
    bool differentInputDiffers = false; ///< a different input changes the hash
};
RollbackResult RunRollback(std::FILE* log = nullptr);

} // namespace meff::tour
