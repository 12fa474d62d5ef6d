// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Tour stop: rollback netcode. A networked game predicts ahead with the inputs it has; when a
// late input arrives it restores the last confirmed snapshot and re-simulates. That only works
// if the replay with the same inputs is bit-identical, which World::GetStateHash makes checkable.
#include "tour.h"

namespace meff::tour
{

namespace
{

constexpr Real kStep = Real(1) / 60;

/// A pile of crates and a player box pushed by "input".
struct Match
{
    World world{WorldDef{}};
    BodyId player{};

    Match()
    {
        const BodyId ground = world.CreateBody(BodyDef{});
        world.CreateShape(ground, ShapeDef{}, MakeOffsetBox(20, 1, {0, -1}, 0));
        for (int i = 0; i < 12; ++i)
        {
            BodyDef crate;
            crate.type = BodyType::Dynamic;
            crate.position = {Real(i % 4) * Real(1.1) - Real(1.5), Real(0.5) + Real(i / 4) * 1.05f};
            world.CreateShape(world.CreateBody(crate), ShapeDef{}, MakeBox(0.5f, 0.5f));
        }
        BodyDef player;
        player.type = BodyType::Dynamic;
        player.position = {-8, 0.5f};
        this->player = world.CreateBody(player);
        world.CreateShape(this->player, ShapeDef{}, MakeBox(0.5f, 0.5f));
    }

    /// One frame with the player's input for it: a push to the right (N).
    std::uint64_t Advance(Real push)
    {
        world.ApplyForceToCenter(player, {push, 0});
        world.Step(kStep);
        return world.GetStateHash();
    }
};

/// The input of one frame: the player pushes on most frames.
Real InputFor(int frame)
{
    return frame % 7 == 3 ? Real(0) : Real(20);
}

} // namespace

RollbackResult RunRollback(std::FILE* log)
{
    Match match;
    constexpr int kConfirmed = 90; // frames both peers agree on
    constexpr int kPredicted = 60; // frames simulated ahead on predicted input
    for (int frame = 0; frame < kConfirmed; ++frame)
    {
        match.Advance(InputFor(frame));
    }
    const WorldSnapshot confirmed = match.world.SaveSnapshot();

    std::vector<std::uint64_t> predicted;
    for (int frame = kConfirmed; frame < kConfirmed + kPredicted; ++frame)
    {
        predicted.push_back(match.Advance(InputFor(frame)));
    }

    // Roll back and replay the same inputs: every step must hash the same.
    match.world.RestoreSnapshot(confirmed);
    RollbackResult result;
    result.replayMatches = true;
    for (int frame = kConfirmed; frame < kConfirmed + kPredicted; ++frame)
    {
        const std::uint64_t hash = match.Advance(InputFor(frame));
        result.replayMatches =
            result.replayMatches && hash == predicted[std::size_t(frame - kConfirmed)];
        ++result.replayedSteps;
    }

    // A late input that differs (no push on the first replayed frame) must change the outcome.
    match.world.RestoreSnapshot(confirmed);
    match.Advance(0);
    for (int frame = kConfirmed + 1; frame < kConfirmed + kPredicted; ++frame)
    {
        match.Advance(InputFor(frame));
    }
    result.differentInputDiffers = match.world.GetStateHash() != predicted.back();

    if (log != nullptr)
    {
        std::fprintf(log,
                     "rollback: replayed %d steps from a snapshot, hashes %s; a different input "
                     "%s the final hash\n",
                     result.replayedSteps, result.replayMatches ? "all equal" : "DIFFER",
                     result.differentInputDiffers ? "changes" : "does NOT change");
    }
    return result;
}

} // namespace meff::tour
