// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The soft step's joint trees (SoftStepSettings::jointTrees, engine/src/solvers/soft_step/
// soft_joint_tree.h): revolute joints that join bodies as a tree are solved together, exactly.
// What must hold: light links holding a heavy body keep their joints closed whatever the mass
// ratio (the sweeps alone let them open by metres), on chains and on branching trees, with and
// without a fixed pivot; and what the tree does not take (loops, bridges, lone joints) steps
// exactly as without it.
#include "analytic_support.h"

#include "meff/world.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace meff;
using namespace meff::analytic;

namespace
{

World MakeTreeWorld(bool trees, Vec2 gravity = {0, -10})
{
    WorldDef def;
    def.gravity = gravity;
    def.solver.kind = SolverKind::SoftStep;
    def.solver.softStep.jointTrees = trees;
    return World{def};
}

/// A revolute joint and its anchor in both bodies' frames, to measure how far it has opened.
struct Hinge
{
    BodyId a, b;
    Vec2 localA, localB;
};

Hinge Join(World& world, BodyId a, BodyId b, Vec2 anchor)
{
    world.CreateJoint(world.MakeRevoluteJointDef(a, b, anchor));
    return {a, b, world.GetLocalPoint(a, anchor), world.GetLocalPoint(b, anchor)};
}

double Gap(const World& world, const Hinge& h)
{
    return double(
        (world.GetWorldPoint(h.a, h.localA) - world.GetWorldPoint(h.b, h.localB)).Length());
}

double SumOfGaps(const World& world, const std::vector<Hinge>& hinges)
{
    double sum = 0;
    for (const Hinge& h : hinges)
    {
        sum += Gap(world, h);
    }
    return sum;
}

/// Links of 0.125 m × 0.5 m, 0.0625 kg (density 1), hanging down from `top` on `parent`, with a
/// 0.5 m box of `ratio` times a link's mass at the end (extreme/chain_heavy_weight.json's chain).
BodyId HangChain(World& world, BodyId parent, Vec2 top, int links, double ratio,
                 std::vector<Hinge>& hinges)
{
    BodyId above = parent;
    Vec2 anchor = top;
    for (int i = 0; i < links; ++i)
    {
        const BodyId link = AddBox(world, BodyType::Dynamic, anchor - Vec2{0, Real(0.25)}, 0,
                                   Real(0.0625), Real(0.25), Material(1, Real(0.6)));
        hinges.push_back(Join(world, above, link, anchor));
        above = link;
        anchor -= Vec2{0, Real(0.5)};
    }
    // A 0.5 m box weighing `ratio` links: density ratio·0.0625/0.25.
    const BodyId weight =
        AddBox(world, BodyType::Dynamic, anchor - Vec2{0, Real(0.25)}, 0, Real(0.25), Real(0.25),
               Material(Real(ratio * 0.0625 / 0.25), Real(0.6)));
    hinges.push_back(Join(world, above, weight, anchor));
    return weight;
}

/// The gap a pivot's implicit spring holds against one sub-step's fall (m): g·h seen through
/// ω²·h (docs/soft-step.md, "Joint trees"): g/ω² at the default 72 Hz.
const double kPivotSag = 10 / std::pow(2 * kPiD * 72, 2);

} // namespace

TEST_CASE("Joint trees: a chain of light links holding 1 to 1000 times a link's mass stays "
          "closed",
          "[soft_step][joint_tree]")
{
    for (const double ratio : {1.0, 100.0, 1000.0})
    {
        CAPTURE(ratio);
        World world = MakeTreeWorld(true);
        std::vector<Hinge> hinges;
        HangChain(world, AddAnchor(world, {0, 5}), {0, 5}, 20, ratio, hinges);
        double largest = 0;
        for (int i = 0; i < 600; ++i)
        {
            world.Step(kDt);
            largest = std::max(largest, SumOfGaps(world, hinges));
        }
        // Solved together, the links fall with the weight: only the pivot's joint gives, by its
        // implicit spring's g/ω² (4.9e-5 m), whatever the weight. Twice that bounds it with
        // the opening half kick's swing and the positions' float rounding (ulp 4.8e-7 m at
        // |y| ≤ 6, up to two per joint, 21 joints: 2e-5 m).
        CHECK(largest <= 2 * kPivotSag);
        CHECK(Gap(world, hinges.front()) >= 0.5 * kPivotSag);
    }
}

TEST_CASE("Joint trees: without them the same chain holding 100 times a link stretches",
          "[soft_step][joint_tree]")
{
    // The sweeps alone hand the weight's pull on one joint per sweep at each light link's own
    // effective mass: the joints open by decimetres to metres (1.48 m summed on
    // extreme/chain_heavy_weight.json, docs/soft-step.md). The tree
    // is what closes them; this keeps the comparison honest.
    World world = MakeTreeWorld(false);
    std::vector<Hinge> hinges;
    HangChain(world, AddAnchor(world, {0, 5}), {0, 5}, 20, 100, hinges);
    double largest = 0;
    for (int i = 0; i < 600; ++i)
    {
        world.Step(kDt);
        largest = std::max(largest, SumOfGaps(world, hinges));
    }
    CHECK(largest >= 0.2); // measured 0.39 m: 4,000 times the tree's bound
}

TEST_CASE("Joint trees: a hub holding three chains with heavy weights stays closed",
          "[soft_step][joint_tree]")
{
    // A branching tree: a hub pinned at its top carries three chains of 6 links, each ending
    // in a box of 300 links' mass; the hub's joint node has three children.
    World world = MakeTreeWorld(true);
    std::vector<Hinge> hinges;
    const BodyId pivot = AddAnchor(world, {0, 5});
    const BodyId hub = AddBox(world, BodyType::Dynamic, {0, Real(4.75)}, 0, Real(1), Real(0.25),
                              Material(1, Real(0.6)));
    hinges.push_back(Join(world, pivot, hub, {0, 5}));
    for (const Real x : {Real(-0.9), Real(0), Real(0.9)})
    {
        HangChain(world, hub, {x, Real(4.5)}, 6, 300, hinges);
    }
    double largest = 0;
    for (int i = 0; i < 600; ++i)
    {
        world.Step(kDt);
        largest = std::max(largest, SumOfGaps(world, hinges));
    }
    // As the chain: the pivot's g/ω², twice for the half kick and rounding (22 joints).
    CHECK(largest <= 2 * kPivotSag);
}

TEST_CASE("Joint trees: a free chain (no pivot) keeps its momentum and its joints",
          "[soft_step][joint_tree]")
{
    // No gravity, no fixed body: the tree is rooted at a body. The links are set spinning and
    // moving; the joints' impulses are internal, so the total momentum stays what it was.
    World world = MakeTreeWorld(true, {0, 0});
    std::vector<Hinge> hinges;
    std::vector<BodyId> links;
    for (int i = 0; i < 10; ++i)
    {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {Real(0.5) * Real(i), 0};
        def.linearVelocity = {1, Real(i % 3) - 1};
        def.angularVelocity = Real(2 * (i % 2) - 1);
        links.push_back(world.CreateBody(def));
        ShapeDef material = Material(Real(1 + i), 0);
        material.filter.groupIndex = -1; // the links pass through each other: joints alone
        world.CreateShape(links.back(), material, MakeBox(Real(0.25), Real(0.0625)));
        if (i > 0)
        {
            hinges.push_back(
                Join(world, links[i - 1], links[i], {Real(0.5) * Real(i) - Real(0.25), 0}));
        }
    }
    const auto momentum = [&]
    {
        Vec2 p{0, 0};
        for (const BodyId link : links)
        {
            p += world.GetMass(link) * world.GetLinearVelocity(link);
        }
        return p;
    };
    // The joints take the links' clashing velocities out in the first step: measure after it.
    world.Step(kDt);
    const Vec2 start = momentum();
    double largest = 0;
    for (int i = 0; i < 300; ++i)
    {
        world.Step(kDt);
        largest = std::max(largest, SumOfGaps(world, hinges));
    }
    const Vec2 end = momentum();
    // Float sums of 10 bodies' m·v (|m·v| ≤ 10 kg·m/s, ulp 1e-6) over 300 steps of equal and
    // opposite impulses: 1e-3 of the 55 kg·m/s moving.
    CHECK(double((end - start).Length()) <= 1e-3);
    // The links swing against each other: their joints' implicit springs give under the
    // centripetal loads, by a millimetre at most in all (measured 0.37 mm).
    CHECK(largest <= 1e-3);
}

TEST_CASE("Joint trees: loops, bridges and lone joints step as without them",
          "[soft_step][joint_tree]")
{
    // None of these is a tree the solve takes (a closed ring, a bridge pinned at both ends, a
    // single pendulum), so the setting must change nothing, bit for bit.
    const auto build = [](bool trees)
    {
        World world = MakeTreeWorld(trees);
        const BodyId left = AddAnchor(world, {-3, 5});
        const BodyId right = AddAnchor(world, {3, 5});
        std::vector<Hinge> hinges;
        BodyId previous = left;
        for (int i = 0; i < 6; ++i)
        {
            const BodyId plank = AddBox(world, BodyType::Dynamic, {Real(-2.5 + i), 5}, 0, Real(0.5),
                                        Real(0.1), Material(1, Real(0.6)));
            Join(world, previous, plank, {Real(-3 + i), 5});
            previous = plank;
        }
        Join(world, previous, right, {3, 5});
        std::vector<BodyId> ring;
        for (int i = 0; i < 4; ++i)
        {
            ring.push_back(AddBox(world, BodyType::Dynamic, {Real(10 + i), 0}, 0, Real(0.5),
                                  Real(0.1), Material(1, Real(0.6))));
        }
        for (int i = 0; i < 4; ++i)
        {
            Join(world, ring[i], ring[(i + 1) % 4], world.GetPosition(ring[(i + 1) % 4]));
        }
        const BodyId bob = AddBall(world, {-10, 0}, {0, 0}, Real(0.2), Material(1, 0));
        Join(world, AddAnchor(world, {-12, 0}), bob, {-12, 0});
        for (int i = 0; i < 120; ++i)
        {
            world.Step(kDt);
        }
        return world.GetStateHash();
    };
    CHECK(build(true) == build(false));
}

namespace
{

/// The largest sum of a swinging chain's gaps over 5 s: 10 links, the weight `ratio` links,
/// hung from `carrier` and pushed sideways at 3 m/s.
double SwingingChain(World& world, BodyId carrier, double ratio)
{
    std::vector<Hinge> hinges;
    const BodyId weight = HangChain(world, carrier, world.GetPosition(carrier), 10, ratio, hinges);
    world.SetLinearVelocity(weight, {3, 0});
    double largest = 0;
    for (int i = 0; i < 300; ++i)
    {
        world.Step(kDt);
        largest = std::max(largest, SumOfGaps(world, hinges));
    }
    return largest;
}

} // namespace

TEST_CASE("Joint trees: a swinging chain stays closed; at 1000:1 it wants 8 sub-steps",
          "[soft_step][joint_tree]")
{
    // Swinging, the links turn against each other and the gaps follow the joints' implicit
    // springs under the relative accelerations: under a millimetre at 100:1 (measured 0.24 mm;
    // the sweeps alone 0.20 m).
    {
        World world = MakeTreeWorld(true);
        CHECK(SwingingChain(world, AddAnchor(world, {0, 5}), 100) <= 1e-3);
    }
    {
        World world = MakeTreeWorld(false);
        CHECK(SwingingChain(world, AddAnchor(world, {0, 5}), 100) >= 0.1);
    }
    // At 1000:1 the tension (625 N) on a link's tiny inertia makes its sideways mode as fast as
    // 335 rad/s, beyond what 240 Hz sub-steps follow with the rows linearised at each sub-step's
    // start: at 4 sub-steps the links jitter (0.83 m summed; the sweeps alone 4.7 m). At 8 the
    // chain holds (measured 0.15 mm; the sweeps alone 2.0 m).
    {
        WorldDef def;
        def.solver.kind = SolverKind::SoftStep;
        def.solver.softStep.substeps = 8;
        World world{def};
        CHECK(SwingingChain(world, AddAnchor(world, {0, 5}), 1000) <= 1e-3);
    }
}

TEST_CASE("Joint trees: a chain hung from a moving kinematic body follows it closed",
          "[soft_step][joint_tree]")
{
    // The pivot's body moves (1 m/s sideways, turning at 1 rad/s): the root joint's body does
    // not move under impulses, and its velocity is part of the pivot's Cdot.
    World world = MakeTreeWorld(true);
    BodyDef def;
    def.type = BodyType::Kinematic;
    def.position = {0, 5};
    def.linearVelocity = {1, 0};
    def.angularVelocity = 1;
    const double largest = SwingingChain(world, world.CreateBody(def), 100);
    CHECK(largest <= 1e-3); // measured 0.26 mm
}
