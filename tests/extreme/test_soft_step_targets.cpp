// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The soft step at its defaults against the targets of issue 16 (60 Hz, 10 s of simulated
// time): each figure is measured as tests/extreme/soft_step_measures.h describes and printed
// (ctest -V) for the documentation (docs/api-guide.md). A met target is asserted as the target; a
// missed one (said so in the documentation and the test's comment) is asserted at what the soft
// step reaches, so that a regression still fails.
#include "soft_step_measures.h"

#include <catch2/catch.hpp>

#include <cstdio>

using namespace meff;
using namespace meff::soft;

namespace
{

constexpr int kFrames = 600; // 10 s at 60 Hz

void Print(const char* scene, const char* measure, double value, const char* target)
{
    std::printf("SOFT_STEP | %s | %s | %.6g | %s\n", scene, measure, value, target);
    std::fflush(stdout);
}

/// Steps the scene `frames` times, calling `after(built)` after each step.
template <typename After>
BuiltScene RunScene(const Scene& scene, int frames, After&& after)
{
    BuiltScene built = BuildWorld(scene);
    for (int f = 0; f < frames; ++f)
    {
        built.world.Step(Real(scene.world.dt));
        after(built);
    }
    return built;
}

} // namespace

TEST_CASE("soft step: the anchored rod follows the exact pendulum within 5 mm and keeps its "
          "energy within 0.5 %",
          "[soft_step][targets]")
{
    const Scene scene = LoadWith("scenes", "anchored_rod", SolverKind::SoftStep);
    const PendulumRun run = RunPendulum(scene, 1, {0, 5}, kFrames, false);
    Print("anchored_rod", "largest distance from the exact pendulum (m)", run.largestDistance,
          "<= 0.005");
    Print("anchored_rod", "energy change at 10 s (fraction of the swing)", run.energyChange,
          "within +-0.005");
    CHECK(run.largestDistance <= 0.005);
    CHECK(std::abs(run.energyChange) <= 0.005);
}

TEST_CASE("soft step: the pendulum on a rod follows the exact pendulum within 1.5 mm",
          "[soft_step][targets]")
{
    const Scene scene = LoadWith("scenes", "pendulum_rod", SolverKind::SoftStep);
    const Vec2 pivot{Real(scene.bodies[0].position.x), Real(scene.bodies[0].position.y)};
    const PendulumRun run = RunPendulum(scene, 1, pivot, kFrames, true);
    Print("pendulum_rod", "largest distance from the exact pendulum (m)", run.largestDistance,
          "<= 0.0015");
    CHECK(run.largestDistance <= 0.0015);
}

TEST_CASE("soft step: chain20's joints open by at most 2 cm", "[soft_step][targets]")
{
    const Scene scene = LoadWith("scenes", "chain20", SolverKind::SoftStep);
    double largest = 0;
    RunScene(scene, kFrames,
             [&](const BuiltScene& built)
             {
                 for (const double gap : AnchorGaps(built))
                 {
                     largest = std::max(largest, gap);
                 }
             });
    Print("chain20", "largest anchor gap (m)", largest, "<= 0.02");
    CHECK(largest <= 0.02);
}

TEST_CASE("soft step: a chain holding a 100x weight keeps the sum of its gaps under 0.5 m",
          "[soft_step][targets]")
{
    const Scene scene = LoadWith("extreme", "chain_heavy_weight", SolverKind::SoftStep);
    double largestSum = 0;
    RunScene(scene, kFrames,
             [&](const BuiltScene& built)
             {
                 double sum = 0;
                 for (const double gap : AnchorGaps(built))
                 {
                     sum += gap;
                 }
                 largestSum = std::max(largestSum, sum);
             });
    Print("chain_heavy_weight 100:1", "largest sum of anchor gaps (m)", largestSum, "<= 0.5");
    // Met by the joint trees (docs/soft-step.md, "Joint trees"): the chain's joints are solved
    // together and only the pivot gives, by g/ω² (measured 5e-5 m; the sweeps alone: 1.48 m).
    CHECK(largestSum <= 0.5);
}

TEST_CASE("soft step: a chain holding a 1000x weight ends with its gaps summing under 1 m",
          "[soft_step][targets]")
{
    Scene scene = LoadWith("extreme", "chain_heavy_weight", SolverKind::SoftStep);
    scene.bodies.back().shapes.at(0).density *= 10; // the weight: 100 → 1000 times a link
    const BuiltScene run = RunScene(scene, kFrames, [](const BuiltScene&) {});
    double sum = 0;
    for (const double gap : AnchorGaps(run))
    {
        sum += gap;
    }
    Print("chain_heavy_weight 1000:1", "sum of anchor gaps at 10 s (m)", sum, "<= 1");
    // Met by the joint trees, as the 100:1 chain: measured 5e-5 m (the sweeps alone: 2.72 m).
    CHECK(sum <= 1.0);
}

namespace
{

struct RestingRun
{
    double displacement = 0; ///< largest displacement of a dynamic body at the end (m)
    double penetration = 0;  ///< deepest penetration beyond rest over the run (m)
};

RestingRun RunResting(const Scene& scene)
{
    BuiltScene built = BuildWorld(scene);
    const std::vector<Vec2> start = Positions(built);
    RestingRun run;
    for (int f = 0; f < kFrames; ++f)
    {
        built.world.Step(Real(scene.world.dt));
        run.penetration = std::max(run.penetration, PenetrationBeyondRest(built.world));
    }
    run.displacement = LargestDisplacement(built, scene, start);
    return run;
}

} // namespace

TEST_CASE("soft step: stack10 moves at most 5 mm and sinks at most 5 mm beyond rest",
          "[soft_step][targets]")
{
    const RestingRun run = RunResting(LoadWith("scenes", "stack10", SolverKind::SoftStep));
    Print("stack10", "largest displacement at 10 s (m)", run.displacement, "<= 0.005");
    Print("stack10", "deepest penetration beyond rest (m)", run.penetration, "<= 0.005");
    CHECK(run.displacement <= 0.005);
    CHECK(run.penetration <= 0.005);
}

TEST_CASE("soft step: pyramid20 moves at most 3 cm", "[soft_step][targets]")
{
    const RestingRun run = RunResting(LoadWith("scenes", "pyramid20", SolverKind::SoftStep));
    Print("pyramid20", "largest displacement at 10 s (m)", run.displacement, "<= 0.03");
    CHECK(run.displacement <= 0.03);
}

TEST_CASE("soft step: the card house and the arch stand", "[soft_step][targets]")
{
    const RestingRun cards = RunResting(LoadWith("extreme", "card_house", SolverKind::SoftStep));
    Print("card_house", "largest displacement at 10 s (m)", cards.displacement,
          "<= 0.012 (missed: 0.0137)");
    // Target 0.012 m (the Box2D back end's at 60 Hz) missed: the flat card falls 12.5 mm
    // before a row exists between it and the cards below (Box2D's first-order fall makes that
    // contact a step earlier), and the cards slide at their feet as it lands. Measured 0.0143 m
    // (Box2D v3: 0.018 m), held to it with 10 %; 0.0139 m since the small groups' contacts are
    // solved together, 0.0137 m since the rows stop at touching (issue 31; at 240 Hz 0.0086 m,
    // as the Box2D back end converges to).
    CHECK(cards.displacement <= 0.0158);
    const RestingRun arch = RunResting(LoadWith("extreme", "arch", SolverKind::SoftStep));
    Print("arch", "largest displacement at 10 s (m)", arch.displacement, "<= 0.005");
    CHECK(arch.displacement <= 0.005);
}

namespace
{

struct MassRatioRun
{
    int framesOnTop = 0;    ///< frames before the heavy box first left the top of the light one
    double penetration = 0; ///< deepest penetration beyond rest while it stayed (m)
};

MassRatioRun RunMassRatio(const char* name)
{
    const Scene scene = LoadWith("extreme", name, SolverKind::SoftStep);
    BuiltScene built = BuildWorld(scene);
    MassRatioRun run;
    // Bodies: ground, light box, heavy box (samples/extreme/make_scenes.py): on top while the
    // heavy box's centre is more than 0.9 m above the light one's (1 m boxes).
    for (int f = 0; f < kFrames; ++f)
    {
        built.world.Step(Real(scene.world.dt));
        const Real light = built.world.GetPosition(built.bodies.at(1)).y;
        const Real heavy = built.world.GetPosition(built.bodies.at(2)).y;
        if (!(heavy > light + Real(0.9)))
        {
            break;
        }
        run.framesOnTop = f + 1;
        run.penetration = std::max(run.penetration, PenetrationBeyondRest(built.world));
    }
    return run;
}

} // namespace

TEST_CASE("soft step: a heavy box stays on a light one at 100:1", "[soft_step][targets]")
{
    const MassRatioRun run = RunMassRatio("mass_ratio_100");
    Print("mass_ratio_100", "frames the heavy box stays on top", run.framesOnTop, "600");
    Print("mass_ratio_100", "deepest penetration beyond rest (m)", run.penetration, "<= 0.02");
    CHECK(run.framesOnTop == kFrames);
    CHECK(run.penetration <= 0.02);
}

TEST_CASE("soft step: a heavy box stays on a light one at 1000:1", "[soft_step][targets]")
{
    const MassRatioRun run = RunMassRatio("mass_ratio_1000");
    Print("mass_ratio_1000", "frames the heavy box stays on top", run.framesOnTop, "600");
    Print("mass_ratio_1000", "deepest penetration beyond rest (m)", run.penetration, "<= 0.02");
    // Met since the contacts of a small group of touching bodies are solved together
    // (soft_contact_direct.h): the load passes through the light box in one update (measured
    // 1.4e-8 m; the sweeps alone sank 73 mm).
    CHECK(run.framesOnTop == kFrames);
    CHECK(run.penetration <= 0.02);
}

TEST_CASE("soft step: overlapping boxes come apart at under 0.5 m/s", "[soft_step][targets]")
{
    const Scene scene = LoadWith("extreme", "overlap_recovery", SolverKind::SoftStep);
    double fastest = 0;
    RunScene(scene, kFrames,
             [&](const BuiltScene& built)
             {
                 for (const BodyId id : built.bodies)
                 {
                     const Vec2 v = built.world.GetLinearVelocity(id);
                     fastest = std::max(fastest, std::hypot(double(v.x), double(v.y)));
                 }
             });
    Print("overlap_recovery", "fastest speed (m/s)", fastest, "<= 0.5");
    CHECK(fastest <= 0.5);
}

// Plausibility (issue 31): what a game needs whatever the accuracy. These scenes have no
// restitution and start without energy beyond their initial velocities, so the bounds below
// are physical invariants, not measured figures: a bound is the target of the issue, each a
// small fraction of what the scene could give back.

namespace
{

/// The kinetic energy of every dynamic body of the scene (J).
double KineticEnergy(const BuiltScene& built)
{
    double energy = 0;
    for (const BodyId id : built.bodies)
    {
        const Vec2 v = built.world.GetLinearVelocity(id);
        const double w = built.world.GetAngularVelocity(id);
        energy += 0.5 * double(built.world.GetMass(id)) * (double(v.x) * v.x + double(v.y) * v.y) +
                  0.5 * double(built.world.GetRotationalInertia(id)) * w * w;
    }
    return energy;
}

/// The rod into the wall: the largest speed of the pair's centre of mass away from the wall
/// (−x) after it first met the wall (m/s).
double RodRebound(bool continuous)
{
    Scene scene = LoadWith("extreme", "rod_into_wall", SolverKind::SoftStep);
    scene.world.continuous = continuous;
    double rebound = 0;
    bool hit = false;
    RunScene(scene, scene.world.frames,
             [&](const BuiltScene& built)
             {
                 // Bodies: wall, front, rear (samples/extreme/make_scenes.py), equal masses.
                 const double v = 0.5 * (double(built.world.GetLinearVelocity(built.bodies[1]).x) +
                                         double(built.world.GetLinearVelocity(built.bodies[2]).x));
                 hit = hit || v < 7.9;
                 rebound = hit ? std::max(rebound, -v) : rebound;
             });
    return rebound;
}

} // namespace

TEST_CASE("soft step: a rod driven into a wall without restitution does not bounce back",
          "[soft_step][targets][plausible]")
{
    // 2560 J arrive at the wall with restitution 0: nothing should come back. Target 0.05 m/s
    // (the Box2D back end leaves 0.031 m/s: its sweeps stop converging there); the soft step
    // once returned 2.54 m/s, a contact's warm start handed on by the rod (docs/soft-step.md).
    for (const bool continuous : {false, true})
    {
        const double rebound = RodRebound(continuous);
        Print(continuous ? "rod_into_wall (continuous)" : "rod_into_wall", "rebound speed (m/s)",
              rebound, "<= 0.05");
        CHECK(rebound <= 0.05);
    }
}

TEST_CASE("soft step: a joint that starts violated closes without giving energy",
          "[soft_step][targets][plausible]")
{
    // Nothing moves at the start and there is no gravity: any kinetic energy is what the
    // joint's 1.5 m gap turned into motion. Targets 1 J at most and 0.1 J at 1 s (the gap
    // would give 668 J if it became velocity, as it once did).
    const Scene scene = LoadWith("extreme", "violated_rod", SolverKind::SoftStep);
    double largest = 0, atOneSecond = 0;
    int frame = 0;
    RunScene(scene, scene.world.frames,
             [&](const BuiltScene& built)
             {
                 const double energy = KineticEnergy(built);
                 largest = std::max(largest, energy);
                 atOneSecond = ++frame == 60 ? energy : atOneSecond;
             });
    Print("violated_rod", "largest kinetic energy (J)", largest, "<= 1");
    Print("violated_rod", "kinetic energy at 1 s (J)", atOneSecond, "<= 0.1");
    CHECK(largest <= 1.0);
    CHECK(atOneSecond <= 0.1);
}

TEST_CASE("soft step: a heavy box dropped on a light one 1000 times lighter stays on top",
          "[soft_step][targets][plausible]")
{
    // The 1000 kg box lands at 4.5 m/s on the 1 kg box; target: on top for the whole run and
    // pressed at most 2 cm beyond rest (the contacts of the three bodies solved together).
    const MassRatioRun run = RunMassRatio("heavy_dropped_on_light");
    Print("heavy_dropped_on_light", "frames the heavy box stays on top", run.framesOnTop, "600");
    Print("heavy_dropped_on_light", "deepest penetration beyond rest (m)", run.penetration,
          "<= 0.02");
    CHECK(run.framesOnTop == kFrames);
    CHECK(run.penetration <= 0.02);
}

TEST_CASE("soft step: a column of twelve 0.4 m boxes stands still",
          "[soft_step][targets][plausible]")
{
    // Built at rest: whatever moves after the first second is drift. Target 5 mm from 1 s to
    // 10 s (an eighth of a box's 40 mm skin-to-skin pitch).
    const Scene scene = LoadWith("extreme", "stack12_small", SolverKind::SoftStep);
    BuiltScene built = BuildWorld(scene);
    std::vector<Vec2> atOneSecond;
    for (int f = 1; f <= kFrames; ++f)
    {
        built.world.Step(Real(scene.world.dt));
        if (f == 60)
        {
            atOneSecond = Positions(built);
        }
    }
    const double drift = LargestDisplacement(built, scene, atOneSecond);
    Print("stack12_small", "largest drift from 1 s to 10 s (m)", drift, "<= 0.005");
    CHECK(drift <= 0.005);
}
