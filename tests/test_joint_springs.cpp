// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Springs on revolute and prismatic joints (Box2D v3's): analytic oracles under every solver back
// end — the undamped period 2π/ω and the damped decay e^(−ζωt) of a torsional oscillator, a
// hanging mass settling at target − m·g/k on a prismatic spring, an arm held near its target
// angle against gravity by torque balance — plus the API, argument and scene-field errors,
// the refusal by `meff validate` and the b2dJson export, and the spring being off by default.
//
// The step of every spring is docs/soft-step.md's exactly damped row ("The exactly damped
// spring"): over a step h its velocity update is v⁺ = e·v − hω²e·C with e = e^(−2ζωh), and
// the position moves by h·v⁺. That discrete oscillator's two eigenvalues have modulus
// e^(−ζωh) — the continuous decay, exactly — and turn by Ωh per step with
//     cos(Ωh) = cosh(ζωh) − (ωh)²·e^(−ζωh)/2,
// so its period 2π/Ω differs from the damped oscillator's 2π/ω_d (ω_d = ω√(1 − ζ²)) by a
// relative ζωh/(2(1 − ζ²)) − (ωh)²/24 to second order: longer by half a step's damping,
// shorter by symplectic Euler's (ωh)²/24. DiscretePeriod below evaluates it exactly.
#include "joints/joint.h"
#include "meff/b2djson.h"
#include "meff/box2d_v3_features.h"
#include "meff/scene.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include "scene_errors.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace meff;

namespace
{

constexpr double kTwoPi = 6.283185307179586;
constexpr Real kDt = Real(1) / Real(60);

World MakeWorld(SolverKind kind, Vec2 gravity)
{
    WorldDef def;
    def.gravity = gravity;
    def.solver.kind = kind;
    def.allowSleep = false; // the oscillations are read to their smallest amplitudes
    return World(def);
}

/// The step each back end integrates the spring over: the whole step, or a sub-step.
double SpringStep(SolverKind kind)
{
    return kind == SolverKind::SoftStep ? double(kDt) / SoftStepSettings{}.substeps : double(kDt);
}

/// The period of the exactly damped step (see the top of the file).
double DiscretePeriod(double hertz, double zeta, double h)
{
    const double wh = kTwoPi * hertz * h;
    const double a = zeta * wh;
    return kTwoPi * h / std::acos(std::cosh(a) - 0.5 * wh * wh * std::exp(-a));
}

/// The continuous period 2π/ω_d and the relative tolerance on a measured one: the step's own
/// lengthening ζωh/(2(1 − ζ²)) plus its shortening (ωh)²/24 (their sum bounds either sign),
/// and 2e-4 for the float angles summed over the run and the crossing interpolation.
struct PeriodOracle
{
    double period;
    double tolerance;
};

PeriodOracle ContinuousPeriod(double hertz, double zeta, double h)
{
    const double omega = kTwoPi * hertz;
    const double wh = omega * h;
    return {kTwoPi / (omega * std::sqrt(1 - zeta * zeta)),
            zeta * wh / (2 * (1 - zeta * zeta)) + wh * wh / 24 + 2e-4};
}

/// Times at which `samples` (taken every kDt from t = kDt) cross 0 upwards, interpolated
/// linearly between the two samples around each crossing.
std::vector<double> UpwardCrossings(const std::vector<double>& samples)
{
    std::vector<double> times;
    for (std::size_t i = 1; i < samples.size(); ++i)
    {
        if (samples[i - 1] < 0 && samples[i] >= 0)
        {
            const double fraction = -samples[i - 1] / (samples[i] - samples[i - 1]);
            times.push_back((double(i) + fraction) * double(kDt));
        }
    }
    return times;
}

double MeanPeriod(const std::vector<double>& crossings)
{
    REQUIRE(crossings.size() >= 2);
    return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

/// A peak of a sampled oscillation: the parabola through the highest sample and its two
/// neighbours (an error of order (ωh)⁴ in the value).
struct Peak
{
    double time, value;
};

std::vector<Peak> Peaks(const std::vector<double>& samples)
{
    std::vector<Peak> peaks;
    for (std::size_t i = 1; i + 1 < samples.size(); ++i)
    {
        const double y0 = samples[i - 1], y1 = samples[i], y2 = samples[i + 1];
        if (y1 > 0 && y1 > y0 && y1 >= y2)
        {
            const double curvature = y0 - 2 * y1 + y2;
            const double offset = 0.5 * (y0 - y2) / curvature;
            peaks.push_back(
                {(double(i + 1) + offset) * double(kDt), y1 - 0.25 * (y0 - y2) * offset});
        }
    }
    return peaks;
}

/// A disc of radius 0.5 m and density 2 pinned at its centre to `ground` by a revolute joint
/// with the given spring: its angle obeys I·θ'' = −I·ω²·(θ − target) − 2·I·ζ·ω·θ', the
/// angular row's mass being the disc's I (the ground is static).
JointId AddSpringDisc(World& world, BodyId ground, Vec2 at, Real hertz, Real zeta, Real target)
{
    const BodyId disc = world.CreateBody({.type = BodyType::Dynamic, .position = at});
    ShapeDef shape;
    shape.density = 2;
    world.CreateShape(disc, shape, Circle{{0, 0}, Real(0.5)});
    RevoluteJointDef def = world.MakeRevoluteJointDef(ground, disc, at);
    def.enableSpring = true;
    def.hertz = hertz;
    def.dampingRatio = zeta;
    def.targetAngle = target;
    return world.CreateJoint(def);
}

/// Steps `world` and samples each joint's body B's angle minus `centre`.
std::vector<std::vector<double>> SampleAngles(World& world, const std::vector<JointId>& joints,
                                              int steps, double centre)
{
    std::vector<std::vector<double>> samples(joints.size());
    for (int i = 0; i < steps; ++i)
    {
        world.Step(kDt);
        for (std::size_t j = 0; j < joints.size(); ++j)
        {
            samples[j].push_back(double(world.GetAngle(world.GetBodyB(joints[j]))) - centre);
        }
    }
    return samples;
}

} // namespace

TEST_CASE("An undamped revolute spring oscillates with period 2π/ω", "[joints][springs][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    const Real hertz = GENERATE(Real(1), Real(3));
    CAPTURE(SolverKindName(kind), hertz);
    World world = MakeWorld(kind, {0, -10}); // the pins carry the discs: gravity exerts no torque
    const BodyId ground = world.CreateBody({});
    // Eight discs: the colour back end would take spring-free revolutes into its SIMD lanes
    // (four at a time); these must stay on the scalar path that has the spring row.
    std::vector<JointId> joints;
    for (int k = 0; k < 8; ++k)
    {
        joints.push_back(AddSpringDisc(world, ground, {Real(2 * k), 0}, hertz, 0, 0));
        world.SetAngularVelocity(world.GetBodyB(joints.back()), 1);
    }
    const auto samples = SampleAngles(world, joints, 600, 0);
    const double h = SpringStep(kind);
    const PeriodOracle oracle = ContinuousPeriod(hertz, 0, h);
    for (const std::vector<double>& angles : samples)
    {
        const double period = MeanPeriod(UpwardCrossings(angles));
        CHECK(period == Approx(oracle.period).epsilon(oracle.tolerance));
        if (kind != SolverKind::SoftStep)
        {
            // One step per kick: the discrete oscillator's period itself, to the interpolation
            // and float rounding (2e-4 relative, as above).
            CHECK(period == Approx(DiscretePeriod(hertz, 0, h)).epsilon(2e-4));
        }
        // Undamped: the symplectic step keeps the amplitude w0/ω (its modified energy is
        // conserved; the amplitude of the sampled angle differs by (ωh)²/8 at most).
        double largest = 0;
        for (std::size_t i = angles.size() / 2; i < angles.size(); ++i)
        {
            largest = std::max(largest, std::abs(angles[i]));
        }
        const double wh = kTwoPi * double(hertz) * double(kDt);
        CHECK(largest == Approx(1 / (kTwoPi * hertz)).epsilon(wh * wh / 8 + 1e-3));
    }
}

TEST_CASE("A damped revolute spring decays as e^(−ζωt) with the damped period",
          "[joints][springs][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    const Real zeta = GENERATE(Real(0.05), Real(0.2));
    CAPTURE(SolverKindName(kind), zeta);
    const Real hertz = 1;
    const Real target = Real(0.3);
    World world = MakeWorld(kind, {0, 0});
    const BodyId ground = world.CreateBody({});
    const JointId joint = AddSpringDisc(world, ground, {0, 0}, hertz, zeta, target);
    world.SetAngularVelocity(world.GetBodyB(joint), 2);
    // Starting at θ = 0, 0.3 rad below the target, with a speed: the motion about the target is
    // A·e^(−ζωt)·sin(ω_d·t + φ); its peaks lie on A·√(1−ζ²)·e^(−ζωt), whatever A and φ.
    const auto samples = SampleAngles(world, {joint}, 480, double(target)).front();
    const double h = SpringStep(kind);
    const double omega = kTwoPi * double(hertz);

    const PeriodOracle oracle = ContinuousPeriod(hertz, zeta, h);
    const double period = MeanPeriod(UpwardCrossings(samples));
    CHECK(period == Approx(oracle.period).epsilon(oracle.tolerance));
    if (kind != SolverKind::SoftStep)
    {
        CHECK(period == Approx(DiscretePeriod(hertz, zeta, h)).epsilon(2e-4));
    }

    // The envelope: every peak over the first, against e^(−ζω·Δt). The step decays exactly at
    // e^(−ζωh) (the eigenvalues' modulus), so what is left is the parabolic interpolation of
    // each peak, of order (ωh)⁴ ≈ 1e-4 relative at 1 Hz and 60 Hz (measured: ≤ 7e-5), and the
    // float angles near 0.3 rad, 3e-8 apart, which the late peaks of 3e-5 rad feel: 1e-3
    // relative or 1e-6 rad.
    const std::vector<Peak> peaks = Peaks(samples);
    REQUIRE(peaks.size() >= 5);
    for (std::size_t k = 1; k < peaks.size(); ++k)
    {
        CAPTURE(k, peaks[k].time);
        const double expected =
            peaks[0].value * std::exp(-double(zeta) * omega * (peaks[k].time - peaks[0].time));
        CHECK(peaks[k].value == Approx(expected).epsilon(1e-3).margin(1e-6));
    }
}

TEST_CASE("A mass hanging on a prismatic spring settles at target − m·g/k",
          "[joints][springs][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(SolverKindName(kind), blockJoints);
    WorldDef worldDef;
    worldDef.gravity = {0, -10};
    worldDef.solver.kind = kind;
    worldDef.solver.blockJoints = blockJoints;
    worldDef.allowSleep = false; // the spring is read where it settles, not where it fell asleep
    World world(worldDef);
    const BodyId ground = world.CreateBody({});
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic, .position = {1, 2}});
    ShapeDef shape;
    shape.density = 3;
    world.CreateShape(box, shape, MakeBox(Real(0.4), Real(0.2))); // m = 0.96 kg
    const Real mass = world.GetMass(box);
    // A slanted rail along (0.6, 0.8): gravity's pull along it is −0.8·m·g.
    PrismaticJointDef def =
        world.MakePrismaticJointDef(ground, box, {1, 2}, {Real(0.6), Real(0.8)});
    def.enableSpring = true;
    def.hertz = 2;
    def.dampingRatio = 1;
    def.targetTranslation = Real(0.5);
    const JointId joint = world.CreateJoint(def);
    CHECK(world.GetJointSpring(joint).target == Real(0.5));

    for (int i = 0; i < 300; ++i)
    {
        world.Step(kDt);
    }
    // The spring's stiffness is its row's mass × ω²: the axial row's mass is m here (the
    // ground is static and the anchor is B's centre, so B's turning is not on the row).
    const double omega = kTwoPi * 2;
    const double k = double(mass) * omega * omega;
    const double rest = 0.5 - double(mass) * 10 * 0.8 / k;
    // Critically damped, 5 s is 63 time constants: at rest. At rest every step's spring
    // impulse holds the weight exactly (the fixed point of the exactly damped row is C =
    // −g_axis/ω², docs/soft-step.md), so what is left is float rounding of positions near
    // 2 m: 1e-5 m.
    CHECK(double(world.GetJointTranslation(joint)) == Approx(rest).margin(1e-5));
    CHECK(double(world.GetJointSpeed(joint)) == Approx(0).margin(1e-5));
    // Across the rail the joint is rigid, but in the soft step its rows are soft at
    // jointHertz (docs/soft-step.md, "Joints") and carry gravity's 0.6·g across the rail by
    // sinking g⊥/(2π·jointHertz)² = 2.9e-5 m along (0.8, −0.6), as a soft row does.
    const double across = kind == SolverKind::SoftStep
                              ? 6 / std::pow(kTwoPi * double(SoftStepSettings{}.jointHertz), 2)
                              : 0;
    CHECK(world.GetPosition(box).x == Approx(1 + 0.6 * rest + 0.8 * across).margin(1e-5));
    CHECK(world.GetPosition(box).y == Approx(2 + 0.8 * rest - 0.6 * across).margin(1e-5));
    // The joint carries the weight: its reaction on the box is m·g upwards (the spring along
    // the rail, the perpendicular row across it), in every back end.
    const JointReaction reaction = world.GetReaction(joint, 1 / kDt);
    CHECK(double(reaction.force.x) == Approx(0).margin(1e-3));
    CHECK(double(reaction.force.y) == Approx(double(mass) * 10).epsilon(1e-4));
}

TEST_CASE("A revolute spring holds an arm at its target angle less the sag of its weight",
          "[joints][springs][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    World world = MakeWorld(kind, {0, -10});
    const BodyId ground = world.CreateBody({});
    // A 2 m × 0.1 m arm of 0.8 kg hinged at its left end, at the origin.
    const BodyId arm = world.CreateBody({.type = BodyType::Dynamic, .position = {1, 0}});
    ShapeDef shape;
    shape.density = 4;
    world.CreateShape(arm, shape, MakeBox(1, Real(0.05)));
    RevoluteJointDef def = world.MakeRevoluteJointDef(ground, arm, {0, 0});
    def.enableSpring = true;
    def.hertz = 3;
    def.dampingRatio = 1;
    def.targetAngle = Real(0.6);
    const JointId joint = world.CreateJoint(def);
    for (int i = 0; i < 360; ++i)
    {
        world.Step(kDt);
    }
    // The spring's stiffness is the angular row's mass × ω²: the arm's inertia about its
    // centre (the ground is static). At rest its torque balances the weight's about the
    // hinge: k·(target − θ) = m·g·(L/2)·cos θ. Newton's method for θ.
    const double mass = double(world.GetMass(arm));
    const double inertia = double(world.GetRotationalInertia(arm)); // about the centre
    const double k = inertia * std::pow(kTwoPi * 3, 2);
    const double load = mass * 10 * 1.0;
    double theta = 0.6;
    for (int i = 0; i < 20; ++i)
    {
        const double f = k * (0.6 - theta) - load * std::cos(theta);
        const double df = -k + load * std::sin(theta);
        theta -= f / df;
    }
    CAPTURE(theta);
    REQUIRE(theta < 0.6 - 0.05); // the weight makes a real sag
    // At rest the balance is the fixed point of the spring row (as for the prismatic
    // spring); the hinge's position correction leaves at most the linear slop (5 mm) at the
    // pin, which turns the 1 m lever by 0 at rest: 1e-4 rad covers float rounding.
    CHECK(double(world.GetAngle(arm)) == Approx(theta).margin(1e-4));
    CHECK(double(world.GetAngularVelocity(arm)) == Approx(0).margin(1e-4));
    // The reaction torque is the spring's: k·(target − θ) = m·g·(L/2)·cos θ.
    CHECK(double(world.GetReaction(joint, 1 / kDt).torque) ==
          Approx(load * std::cos(theta)).epsilon(1e-3));
}

TEST_CASE("Joint springs: SetJointSpring and GetJointSpring, their errors, waking",
          "[joints][springs][api]")
{
    World world = MakeWorld(SolverKind::Box2D, {0, 0});
    const BodyId ground = world.CreateBody({});
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic, .position = {0, 0}});
    world.CreateShape(box, {}, MakeBox(Real(0.5), Real(0.5)));
    const JointId revolute = world.CreateJoint(world.MakeRevoluteJointDef(ground, box, {0, 0}));
    const JointId prismatic =
        world.CreateJoint(world.MakePrismaticJointDef(ground, box, {0, 0}, {1, 0}));
    const JointId distance =
        world.CreateJoint(world.MakeDistanceJointDef(ground, box, {0, 1}, {0, 0}));

    // Off by default, with zero frequency, damping and target.
    const JointSpring none = world.GetJointSpring(revolute);
    CHECK(!none.enable);
    CHECK(none.hertz == 0);
    CHECK(none.dampingRatio == 0);
    CHECK(none.target == 0);

    world.SetJointSpring(revolute, {true, 4, Real(0.5), Real(-0.25)});
    const JointSpring set = world.GetJointSpring(revolute);
    CHECK(set.enable);
    CHECK(set.hertz == 4);
    CHECK(set.dampingRatio == Real(0.5));
    CHECK(set.target == Real(-0.25));
    world.SetJointSpring(prismatic, {true, 1, 0, 2});
    CHECK(world.GetJointSpring(prismatic).target == 2);

    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    CHECK_THROWS_WITH(world.SetJointSpring(revolute, {true, -1, 0, 0}),
                      Catch::Contains("World::SetJointSpring: hertz") && Catch::Contains(">= 0"));
    CHECK_THROWS_WITH(world.SetJointSpring(prismatic, {true, 1, -Real(0.1), 0}),
                      Catch::Contains("World::SetJointSpring: dampingRatio"));
    CHECK_THROWS_WITH(world.SetJointSpring(prismatic, {true, 1, 0, nan}),
                      Catch::Contains("World::SetJointSpring: target") &&
                          Catch::Contains("finite"));
    CHECK_THROWS_WITH(world.SetJointSpring(distance, {true, 1, 0, 0}),
                      "World::SetJointSpring: the joint has no spring (only revolute and "
                      "prismatic joints do)");
    CHECK_THROWS_AS(world.GetJointSpring(distance), InvalidArgument);
    // A refused call changes nothing.
    CHECK(world.GetJointSpring(revolute).hertz == 4);

    // A changed spring wakes the bodies; an unchanged one does not.
    WorldDef sleepy;
    sleepy.gravity = {0, 0};
    sleepy.allowSleep = true;
    World quiet(sleepy);
    const BodyId pinned = quiet.CreateBody({});
    const BodyId wheel = quiet.CreateBody({.type = BodyType::Dynamic});
    quiet.CreateShape(wheel, {}, Circle{{0, 0}, 1});
    const JointId pin = quiet.CreateJoint(quiet.MakeRevoluteJointDef(pinned, wheel, {0, 0}));
    for (int i = 0; i < 120; ++i)
    {
        quiet.Step(kDt);
    }
    REQUIRE(!quiet.IsAwake(wheel));
    quiet.SetJointSpring(pin, quiet.GetJointSpring(pin));
    CHECK(!quiet.IsAwake(wheel));
    quiet.SetJointSpring(pin, {true, 2, 1, 1});
    CHECK(quiet.IsAwake(wheel));
    // Turned on later, the spring turns the wheel to its target, until the wheel falls asleep
    // on the way in: once its speed stays below the sleep tolerance (2°/s = 0.035 rad/s) for
    // 0.5 s. Critically damped at ω = 4π rad/s, that leaves it within 0.035/ω = 2.8e-3 rad.
    for (int i = 0; i < 240; ++i)
    {
        quiet.Step(kDt);
    }
    CHECK(quiet.GetAngle(wheel) == Approx(1).margin(2.8e-3));
    CHECK(quiet.GetAngle(wheel) < 1); // approached from below, without overshoot
}

TEST_CASE("Joint spring definitions reject bad values", "[joints][springs][make]")
{
    using detail::MakeJoint;
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    RevoluteJointDef revolute;
    revolute.hertz = -2;
    CHECK_THROWS_WITH(MakeJoint(revolute, 0, 1),
                      "RevoluteJointDef::hertz: must be finite and >= 0, got -2");
    revolute.hertz = 1;
    revolute.dampingRatio = -Real(0.5);
    CHECK_THROWS_WITH(MakeJoint(revolute, 0, 1),
                      "RevoluteJointDef::dampingRatio: must be finite and >= 0, got -0.5");
    revolute.dampingRatio = 0;
    revolute.targetAngle = nan;
    CHECK_THROWS_WITH(MakeJoint(revolute, 0, 1), Catch::Contains("RevoluteJointDef::targetAngle") &&
                                                     Catch::Contains("must be finite"));
    PrismaticJointDef prismatic;
    prismatic.hertz = -1;
    CHECK_THROWS_WITH(MakeJoint(prismatic, 0, 1),
                      "PrismaticJointDef::hertz: must be finite and >= 0, got -1");
    prismatic.hertz = 0;
    prismatic.dampingRatio = nan;
    CHECK_THROWS_WITH(MakeJoint(prismatic, 0, 1),
                      Catch::Contains("PrismaticJointDef::dampingRatio") &&
                          Catch::Contains("must be finite"));
    prismatic.dampingRatio = 0;
    prismatic.targetTranslation = std::numeric_limits<Real>::infinity();
    CHECK_THROWS_WITH(MakeJoint(prismatic, 0, 1),
                      Catch::Contains("PrismaticJointDef::targetTranslation") &&
                          Catch::Contains("must be finite"));
}

TEST_CASE("A joint spring that is off changes nothing: the Box2D back end steps as without it",
          "[joints][springs][box2d]")
{
    // The golden tests step libbox2d 2.4.1 beside meff's revolute and prismatic joints and
    // `meff validate` compares every sample; here: spring fields set but the spring off give
    // the same states, bit for bit, as the default definitions, through motors and limits.
    auto run = [](bool springFields)
    {
        World world = MakeWorld(SolverKind::Box2D, {0, -10});
        const BodyId ground = world.CreateBody({});
        const BodyId arm = world.CreateBody({.type = BodyType::Dynamic, .position = {1, 0}});
        world.CreateShape(arm, {}, MakeBox(1, Real(0.1)));
        const BodyId slider = world.CreateBody({.type = BodyType::Dynamic, .position = {0, 3}});
        world.CreateShape(slider, {}, MakeBox(Real(0.3), Real(0.3)));
        RevoluteJointDef hinge = world.MakeRevoluteJointDef(ground, arm, {0, 0});
        hinge.enableLimit = true;
        hinge.lowerAngle = -1;
        hinge.upperAngle = Real(0.5);
        hinge.enableMotor = true;
        hinge.motorSpeed = 1;
        hinge.maxMotorTorque = 3;
        PrismaticJointDef rail = world.MakePrismaticJointDef(arm, slider, {0, 3}, {1, 1});
        rail.enableLimit = true;
        rail.lowerTranslation = -1;
        rail.upperTranslation = 1;
        if (springFields)
        {
            hinge.hertz = 5;
            hinge.dampingRatio = Real(0.7);
            hinge.targetAngle = Real(0.2);
            rail.hertz = 3;
            rail.dampingRatio = 1;
            rail.targetTranslation = Real(0.4);
        }
        world.CreateJoint(hinge);
        world.CreateJoint(rail);
        std::vector<std::uint64_t> hashes;
        for (int i = 0; i < 200; ++i)
        {
            world.Step(kDt);
            hashes.push_back(world.GetStateHash());
        }
        return hashes;
    };
    CHECK(run(true) == run(false));
}

TEST_CASE("Soft step: prismatic and wheel joints report their reaction along their axes",
          "[joints][springs][soft_step]")
{
    // The soft step solves the line joints' rows on axes of its own; their reaction must use
    // the step's axes (they were never set: the force came out as 0). A box hangs still on a
    // vertical line joint with a limit at 0 holding it: the joint carries m·g.
    const bool wheel = GENERATE(false, true);
    CAPTURE(wheel);
    World world = MakeWorld(SolverKind::SoftStep, {0, -10});
    const BodyId ground = world.CreateBody({});
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic, .position = {0, 1}});
    world.CreateShape(box, {}, MakeBox(Real(0.5), Real(0.5))); // 1 kg
    JointId joint;
    if (wheel)
    {
        WheelJointDef def = world.MakeWheelJointDef(ground, box, {0, 1}, {0, 1});
        def.enableLimit = true;
        joint = world.CreateJoint(def);
    }
    else
    {
        PrismaticJointDef def = world.MakePrismaticJointDef(ground, box, {0, 1}, {0, 1});
        def.enableLimit = true;
        joint = world.CreateJoint(def);
    }
    for (int i = 0; i < 60; ++i)
    {
        world.Step(kDt);
    }
    const JointReaction reaction = world.GetReaction(joint, 1 / kDt);
    // At rest on the limit the impulses hold the weight each step: 1e-3 relative covers the
    // soft rows' residual motion.
    CHECK(double(reaction.force.y) == Approx(10).epsilon(1e-3));
    CHECK(double(reaction.force.x) == Approx(0).margin(1e-3));
}

TEST_CASE("Scene files: joint springs load, build, and report bad fields by path",
          "[scene][joints][springs]")
{
    using test::ErrorsOf;
    const std::string head = R"({ "meff_scene": 1, "world": {"gravity": [0, -10]},
        "bodies": [ { "name": "ground", "type": "static" },
                    { "name": "box", "type": "dynamic", "position": [0, 1],
                      "shapes": [ { "type": "circle", "radius": 0.5 } ] } ],)";
    const Scene scene = ParseScene(head + R"(
        "joints": [ { "type": "revolute", "name": "r", "body_a": "ground", "body_b": "box",
                      "anchor": [0, 1], "enable_spring": true, "stiffness_hz": 2,
                      "damping_ratio": 0.5, "target_angle": 0.25 },
                    { "type": "prismatic", "name": "p", "body_a": "ground", "body_b": "box",
                      "anchor": [0, 1], "axis": [0, 1], "enable_spring": true,
                      "stiffness_hz": 1.5, "target_translation": -0.5 },
                    { "type": "revolute", "name": "plain", "body_a": "ground",
                      "body_b": "box", "anchor": [0, 1] } ] })",
                                   "x.json");
    REQUIRE(scene.joints.size() == 3);
    CHECK(scene.joints[0].enableSpring);
    CHECK(scene.joints[0].stiffnessHz == 2);
    CHECK(scene.joints[0].dampingRatio == 0.5);
    CHECK(scene.joints[0].targetAngle == 0.25);
    CHECK(scene.joints[1].targetTranslation == -0.5);
    CHECK(scene.joints[1].dampingRatio == 0);
    CHECK(!scene.joints[2].enableSpring);
    const BuiltScene built = BuildWorld(scene);
    const JointSpring r = built.world.GetJointSpring(built.joints[0]);
    CHECK(r.enable);
    CHECK(r.hertz == 2);
    CHECK(r.dampingRatio == Real(0.5));
    CHECK(r.target == Real(0.25));
    CHECK(built.world.GetJointSpring(built.joints[1]).target == Real(-0.5));
    CHECK(!built.world.GetJointSpring(built.joints[2]).enable);

    CHECK(ErrorsOf(head + R"(
        "joints": [ { "type": "revolute", "name": "r", "body_a": "ground", "body_b": "box",
                      "anchor": [0, 1], "enable_spring": 1, "stiffness_hz": -2,
                      "damping_ratio": -0.5, "target_angle": "up" },
                    { "type": "prismatic", "name": "p", "body_a": "ground", "body_b": "box",
                      "anchor": [0, 1], "axis": [0, 1], "target_angle": 1 } ] })") ==
          std::vector<std::string>{
              "x.json: joints[0].enable_spring: must be true or false, got 1",
              "x.json: joints[0].stiffness_hz: must be >= 0, got -2",
              "x.json: joints[0].damping_ratio: must be >= 0, got -0.5",
              "x.json: joints[0].target_angle: must be a number, got \"up\"",
              "x.json: joints[1].target_angle: unknown field (known fields here: type, name, "
              "body_a, body_b, collide_connected, local_anchor_a, local_anchor_b, anchor, "
              "local_axis_a, axis, enable_limit, lower_translation, upper_translation, "
              "enable_motor, motor_speed, reference_angle, max_motor_force, enable_spring, "
              "stiffness_hz, damping_ratio, target_translation)"});

    // Box2D 2.4.1 has no joint spring: validate and the b2dJson export refuse it by field.
    const std::vector<std::string> lacking = FieldsBox2D241Lacks(scene, "so: refused");
    CHECK(lacking == std::vector<std::string>{
                         "x.json: joints[0].enable_spring: a spring on a revolute joint (Box2D "
                         "v3's), which Box2D 2.4.1 does not have; so: refused",
                         "x.json: joints[1].enable_spring: a spring on a prismatic joint (Box2D "
                         "v3's), which Box2D 2.4.1 does not have; so: refused"});
    CHECK_THROWS_AS(ExportB2dJson(scene), SceneError);
    Scene off = scene;
    off.joints[0].enableSpring = false;
    off.joints[1].enableSpring = false;
    CHECK(FieldsBox2D241Lacks(off, "").empty());
}

TEST_CASE("spring_gadgets.json: every back end brings the springs to the rests it describes",
          "[scene][joints][springs][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    Scene scene = LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/v3/spring_gadgets.json");
    scene.world.solver.kind = kind;
    BuiltScene built = BuildWorld(scene);
    World& world = built.world;
    for (int i = 0; i < 600; ++i)
    {
        world.Step(kDt);
    }
    const auto joint = [&](const char* name)
    {
        for (std::size_t j = 0; j < scene.joints.size(); ++j)
        {
            if (scene.joints[j].name == name)
            {
                return built.joints[j];
            }
        }
        FAIL("no joint " << name);
        return JointId{};
    };
    // The weight on its 1 Hz, ζ = 0.2 prismatic spring: after 10 s (e^(−ζω·10) = 3.5e-6 of
    // its 0.25 m swing left) it hangs g/ω² = 10/(2π)² = 0.2533 m below its target.
    CHECK(double(world.GetJointTranslation(joint("hanging_spring"))) ==
          Approx(-10 / (kTwoPi * kTwoPi)).margin(1e-4));
    // The flywheel's 0.5 Hz, ζ = 0.1 spring: 10 s leave e^(−ζω·10) = 4 % of its 0.95 rad
    // swing (3/π), 0.04 rad.
    const BodyId flywheel = world.GetBodyB(joint("flywheel_spring"));
    CHECK(std::abs(double(world.GetAngle(flywheel))) < 0.05);
    // The plunger ends pressed on its upper limit (its target lies beyond); the limit's
    // position pass leaves up to the linear slop, 5 mm.
    CHECK(double(world.GetJointTranslation(joint("plunger_spring"))) == Approx(0.6).margin(0.005));
}
