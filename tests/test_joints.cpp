// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Joint solvers driven directly with hand-built SolverData: the revolute joint (block and
// scalar-row point constraint, motor, limits, position pass), the distance joint (rigid rod,
// spring, limits) and MakeJoint's validation. Expected values are derived independently
// (in double where it matters) from the seed's scalar effective mass
//   k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB,   λ = −(Jv + bias)/k.
#include "joints/joint.h"

#include "error_checks.h"
#include "meff/error.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace meff;
using namespace meff::detail;

namespace
{

constexpr Real kDt = Real(1) / Real(60);

// A float result built from O(1) inputs in ~10-20 operations carries a few ulp (6e-8 each)
// of round-off: 1e-5 is far above that and far below any error a wrong formula makes.
constexpr double kVelocityTol = 1e-5;

StepContext MakeStep(Real dt = kDt, bool warmStarting = true, bool blockJoints = true)
{
    StepContext step;
    step.dt = dt;
    step.invDt = Real(1) / dt;
    step.dtRatio = 1;
    step.solver.warmStarting = warmStarting;
    step.solver.blockJoints = blockJoints;
    return step;
}

/// Two bodies in solver slots 0 (A) and 1 (B).
struct Rig
{
    Position positions[2];
    Velocity velocities[2];
    JointBody a, b;

    SolverData Data(const StepContext& step)
    {
        SolverData data;
        data.step = step;
        data.positions = positions;
        data.velocities = velocities;
        return data;
    }
};

JointBody StaticBody()
{
    JointBody body;
    body.solverIndex = 0;
    return body;
}

JointBody DynamicBody(std::int32_t index, Real mass, Real inertia, Vec2 localCenter)
{
    JointBody body;
    body.solverIndex = index;
    body.localCenter = localCenter;
    body.invMass = Real(1) / mass;
    body.invI = Real(1) / inertia;
    return body;
}

/// Centre of mass that puts a body's local anchor on a world point at the given angle.
Vec2 CenterForAnchor(Vec2 worldAnchor, Vec2 localAnchor, Vec2 localCenter, Real angle)
{
    return worldAnchor - Mul(Rot(angle), localAnchor - localCenter);
}

Vec2 WorldAnchor(const Rig& rig, int index, Vec2 localAnchor, Vec2 localCenter)
{
    const Position& p = rig.positions[index];
    return p.c + Mul(Rot(p.a), localAnchor - localCenter);
}

// The pendulum: a 2 m bar of 1 kg (I = mL²/12 = 1/3 kg·m² about its centre), its centre of
// mass slightly off the geometric middle so that localCenter matters, pinned at one end to
// static ground at the origin, at a generic angle so that both point rows are coupled.
constexpr Real kBarMass = 1;
constexpr Real kBarInertia = Real(1) / Real(3);
const Vec2 kBarCenter{Real(0.1), Real(0.05)};
const Vec2 kBarAnchor{-1, 0};
constexpr Real kBarAngle = Real(0.7);

struct Pendulum
{
    Rig rig;
    RevoluteJoint joint;
};

Pendulum MakePendulum(Vec2 v, Real w)
{
    Pendulum p;
    p.rig.a = StaticBody();
    p.rig.b = DynamicBody(1, kBarMass, kBarInertia, kBarCenter);
    p.rig.positions[1].c = CenterForAnchor({0, 0}, kBarAnchor, kBarCenter, kBarAngle);
    p.rig.positions[1].a = kBarAngle;
    p.rig.velocities[1].v = v;
    p.rig.velocities[1].w = w;
    p.joint.localAnchorA = {0, 0};
    p.joint.localAnchorB = kBarAnchor;
    return p;
}

/// Relative velocity of the anchors with the joint's current lever arms.
Vec2 AnchorRelativeVelocity(const Rig& rig, const RevoluteJoint& j)
{
    const Velocity& A = rig.velocities[0];
    const Velocity& B = rig.velocities[1];
    return B.v + Cross(B.w, j.rB) - A.v - Cross(A.w, j.rA);
}

/// Block impulse −K⁻¹·Cdot in double, K from the seed's formula.
void BlockImpulse(const RevoluteJoint& j, Vec2 cdot, double& px, double& py)
{
    const double mA = j.invMassA, mB = j.invMassB, iA = j.invIA, iB = j.invIB;
    const double ax = j.rA.x, ay = j.rA.y, bx = j.rB.x, by = j.rB.y;
    const double k11 = mA + mB + iA * ay * ay + iB * by * by;
    const double k22 = mA + mB + iA * ax * ax + iB * bx * bx;
    const double k12 = -iA * ax * ay - iB * bx * by;
    const double det = k11 * k22 - k12 * k12;
    px = -(k22 * cdot.x - k12 * cdot.y) / det;
    py = -(k11 * cdot.y - k12 * cdot.x) / det;
}

/// A world for the island tests: bodies in solver order and the joints between them.
struct MiniWorld
{
    std::vector<JointBody> bodies;
    std::vector<Real> masses;
    std::vector<Position> positions;
    std::vector<Velocity> velocities;
    std::vector<Joint> joints;
};

/// One step of Box2D's b2Island::Solve restricted to joints: integrate velocities, init
/// joints (warm start), velocity iterations, integrate positions with the translation and
/// rotation caps, position iterations with early exit.
void StepWorld(MiniWorld& w, const StepContext& step, Vec2 gravity)
{
    const Real h = step.dt;
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
    {
        if (w.bodies[i].invMass > 0)
        {
            w.velocities[i].v += h * w.bodies[i].invMass * (w.masses[i] * gravity);
        }
    }
    SolverData data;
    data.step = step;
    data.positions = w.positions.data();
    data.velocities = w.velocities.data();
    for (Joint& j : w.joints)
    {
        InitJointVelocityConstraints(j, w.bodies[j.bodyA], w.bodies[j.bodyB], data);
    }
    for (int it = 0; it < step.solver.velocityIterations; ++it)
    {
        for (Joint& j : w.joints)
        {
            SolveJointVelocityConstraints(j, data);
        }
    }
    const Tolerances& tol = step.tolerances;
    for (std::size_t i = 0; i < w.bodies.size(); ++i)
    {
        Vec2 v = w.velocities[i].v;
        Real om = w.velocities[i].w;
        const Vec2 translation = h * v;
        if (Dot(translation, translation) > tol.maxTranslation * tol.maxTranslation)
        {
            v *= tol.maxTranslation / translation.Length();
        }
        const Real rotation = h * om;
        if (rotation * rotation > tol.maxRotation * tol.maxRotation)
        {
            om *= tol.maxRotation / std::abs(rotation);
        }
        w.positions[i].c += h * v;
        w.positions[i].a += h * om;
        w.velocities[i].v = v;
        w.velocities[i].w = om;
    }
    for (int it = 0; it < step.solver.positionIterations; ++it)
    {
        bool ok = true;
        for (Joint& j : w.joints)
        {
            ok = SolveJointPositionConstraints(j, data) && ok;
        }
        if (ok)
        {
            break;
        }
    }
}

/// The pendulum of the unit tests as a one-joint MiniWorld (ground in slot 0).
MiniWorld PendulumWorld()
{
    MiniWorld w;
    w.bodies = {StaticBody(), DynamicBody(1, kBarMass, kBarInertia, kBarCenter)};
    w.masses = {0, kBarMass};
    w.positions.resize(2);
    w.velocities.resize(2);
    w.positions[1].c = CenterForAnchor({0, 0}, kBarAnchor, kBarCenter, kBarAngle);
    w.positions[1].a = kBarAngle;
    RevoluteJointDef def;
    def.localAnchorB = kBarAnchor;
    w.joints.push_back(MakeJoint(def, 0, 1));
    return w;
}

Vec2 AnchorGap(const MiniWorld& w, const Joint& j, Vec2 localA, Vec2 localB)
{
    const JointBody& A = w.bodies[j.bodyA];
    const JointBody& B = w.bodies[j.bodyB];
    const Position& pA = w.positions[j.bodyA];
    const Position& pB = w.positions[j.bodyB];
    return (pB.c + Mul(Rot(pB.a), localB - B.localCenter)) -
           (pA.c + Mul(Rot(pA.a), localA - A.localCenter));
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Revolute joint

TEST_CASE("Revolute block solve removes the anchor's relative velocity in one pass",
          "[joints][revolute]")
{
    Pendulum p = MakePendulum({Real(0.3), -2}, Real(0.7));
    SolverData data = p.rig.Data(MakeStep(kDt, false, true));
    InitVelocityConstraints(p.joint, p.rig.a, p.rig.b, data);

    const Vec2 before = AnchorRelativeVelocity(p.rig, p.joint);
    REQUIRE(before.Length() > Real(1)); // the test starts far from satisfied
    double px, py;
    BlockImpulse(p.joint, before, px, py);

    SolveVelocityConstraints(p.joint, data);
    const Vec2 after = AnchorRelativeVelocity(p.rig, p.joint);
    CHECK(after.x == Approx(0).margin(kVelocityTol));
    CHECK(after.y == Approx(0).margin(kVelocityTol));
    // The accumulated impulse is the exact 2×2 solution (relative float round-off).
    CHECK(p.joint.impulse.x == Approx(px).epsilon(1e-5));
    CHECK(p.joint.impulse.y == Approx(py).epsilon(1e-5));
    // Momentum bookkeeping on B: Δv = P/m, Δw = (rB × P)/I.
    CHECK(p.rig.velocities[1].v.x == Approx(0.3 + px / kBarMass).epsilon(1e-5));
    const double dw = (p.joint.rB.x * py - p.joint.rB.y * px) / kBarInertia;
    CHECK(p.rig.velocities[1].w == Approx(0.7 + dw).epsilon(1e-5));
    // The static ground is untouched.
    CHECK(p.rig.velocities[0].v == Vec2(0, 0));
    CHECK(p.rig.velocities[0].w == 0);
}

TEST_CASE("Revolute scalar rows: each row has the seed's k and the sweeps converge",
          "[joints][revolute]")
{
    Pendulum p = MakePendulum({Real(0.3), -2}, Real(0.7));
    SolverData data = p.rig.Data(MakeStep(kDt, false, false));
    InitVelocityConstraints(p.joint, p.rig.a, p.rig.b, data);
    const Vec2 before = AnchorRelativeVelocity(p.rig, p.joint);
    double px, py;
    BlockImpulse(p.joint, before, px, py);

    // First sweep, by hand: the x row alone with k_x = mA + mB + iA·rA.y² + iB·rB.y²
    // (seed with n = x̂: (r×x̂)² = r.y²).
    const double iB = 1.0 / kBarInertia;
    const double rBx = p.joint.rB.x, rBy = p.joint.rB.y;
    const double kx = 1.0 + iB * rBy * rBy;
    const double ky = 1.0 + iB * rBx * rBx;
    const double lambdaX = -before.x / kx;
    // After the x row, B's anchor y-speed changes by (rB.x · Δw) with Δw = iB·(rB × (λx, 0)).
    const double cdotY = before.y + rBx * (iB * (-rBy * lambdaX));
    const double lambdaY = -cdotY / ky;

    SolveVelocityConstraints(p.joint, data);
    CHECK(p.joint.impulse.x == Approx(lambdaX).epsilon(1e-5));
    CHECK(p.joint.impulse.y == Approx(lambdaY).epsilon(1e-5));
    const Vec2 afterOne = AnchorRelativeVelocity(p.rig, p.joint);
    CHECK(afterOne.y == Approx(0).margin(kVelocityTol)); // the last row solved is exact
    // ... but the y row disturbed the x row through the shared rotation: one sweep is not the
    // block solution. (Coupling here is K12²/(K11·K22) ≈ 0.3, so the residual is large.)
    CHECK(std::abs(afterOne.x) > Real(0.05));

    // Gauss-Seidel on an SPD 2×2 contracts by K12²/(K11·K22) per sweep: 40 sweeps reach
    // float round-off, and the accumulated impulse reaches the block solution.
    for (int i = 0; i < 40; ++i)
    {
        SolveVelocityConstraints(p.joint, data);
    }
    const Vec2 after = AnchorRelativeVelocity(p.rig, p.joint);
    CHECK(after.x == Approx(0).margin(kVelocityTol));
    CHECK(after.y == Approx(0).margin(kVelocityTol));
    CHECK(p.joint.impulse.x == Approx(px).epsilon(1e-4));
    CHECK(p.joint.impulse.y == Approx(py).epsilon(1e-4));
}

TEST_CASE("Revolute warm start applies the stored impulses scaled by dtRatio", "[joints][revolute]")
{
    // Two dynamic bodies, so that both sides of M⁻¹·Jᵀ·P are checked.
    Rig rig;
    rig.a = DynamicBody(0, 2, Real(0.5), {0, 0});
    rig.b = DynamicBody(1, kBarMass, kBarInertia, kBarCenter);
    rig.positions[0].a = Real(-0.2);
    rig.positions[1].c = CenterForAnchor({0, 0}, kBarAnchor, kBarCenter, kBarAngle);
    rig.positions[1].a = kBarAngle;
    rig.velocities[0].v = {1, 2};
    rig.velocities[0].w = 3;
    rig.velocities[1].v = {-1, Real(0.5)};
    rig.velocities[1].w = -2;

    RevoluteJoint j;
    j.localAnchorB = kBarAnchor;
    j.enableMotor = true;
    j.maxMotorTorque = 100;
    j.enableLimit = true;
    j.lowerAngle = -1;
    j.upperAngle = 2;
    j.impulse = {Real(0.4), Real(-1.2)};
    j.motorImpulse = Real(0.3);
    j.lowerImpulse = Real(0.2);
    j.upperImpulse = Real(0.1);

    StepContext step = MakeStep(kDt, true, true);
    step.dtRatio = Real(0.5); // the previous step was twice as long
    SolverData data = rig.Data(step);
    InitVelocityConstraints(j, rig.a, rig.b, data);

    CHECK(j.impulse.x == Approx(0.2));
    CHECK(j.impulse.y == Approx(-0.6));
    CHECK(j.motorImpulse == Approx(0.15));
    CHECK(j.lowerImpulse == Approx(0.1));
    CHECK(j.upperImpulse == Approx(0.05));

    const double Px = 0.2, Py = -0.6;
    const double axial = 0.15 + 0.1 - 0.05; // the upper limit pushes the other way
    CHECK(rig.velocities[0].v.x == Approx(1 - 0.5 * Px));
    CHECK(rig.velocities[0].v.y == Approx(2 - 0.5 * Py));
    CHECK(rig.velocities[0].w ==
          Approx(3 - 2.0 * ((double(j.rA.x) * Py - double(j.rA.y) * Px) + axial)));
    CHECK(rig.velocities[1].v.x == Approx(-1 + Px));
    CHECK(rig.velocities[1].v.y == Approx(0.5 + Py));
    CHECK(rig.velocities[1].w ==
          Approx(-2 + 3.0 * ((double(j.rB.x) * Py - double(j.rB.y) * Px) + axial)));

    SECTION("without warm starting the stored impulses are dropped and nothing is applied")
    {
        data.step.solver.warmStarting = false;
        rig.velocities[1].v = {-1, Real(0.5)};
        InitVelocityConstraints(j, rig.a, rig.b, data);
        CHECK(j.impulse == Vec2(0, 0));
        CHECK(j.motorImpulse == 0);
        CHECK(j.lowerImpulse == 0);
        CHECK(j.upperImpulse == 0);
        CHECK(rig.velocities[1].v == Vec2(-1, Real(0.5)));
    }
    SECTION("a disabled limit or motor drops its impulse even when warm starting")
    {
        j.enableLimit = false;
        j.enableMotor = false;
        InitVelocityConstraints(j, rig.a, rig.b, data);
        CHECK(j.motorImpulse == 0);
        CHECK(j.lowerImpulse == 0);
        CHECK(j.upperImpulse == 0);
        CHECK(j.impulse.x == Approx(0.1)); // scaled by dtRatio once more
    }
}

TEST_CASE("Revolute motor reaches its speed or is clamped by maxMotorTorque·dt",
          "[joints][revolute]")
{
    // A wheel pinned at its centre of mass (rB = 0): the point rows cannot change its spin,
    // so the motor row alone decides wB. Angular k = 1/IB = 2.
    Rig rig;
    rig.a = StaticBody();
    rig.b = DynamicBody(1, 3, Real(0.5), {0, 0});
    rig.velocities[1].w = Real(-1);
    RevoluteJoint j;
    j.enableMotor = true;
    j.motorSpeed = 2;

    SECTION("enough torque: one pass reaches the target speed")
    {
        j.maxMotorTorque = 1000;
        SolverData data = rig.Data(MakeStep(kDt, false));
        InitVelocityConstraints(j, rig.a, rig.b, data);
        SolveVelocityConstraints(j, data);
        CHECK(rig.velocities[1].w == Approx(2).margin(kVelocityTol));
        // λ = −(Cdot)/k = −(−1 − 2)·IB = 1.5 N·m·s
        CHECK(j.motorImpulse == Approx(1.5));
        CHECK(GetJointReaction(Joint{JointType::Revolute, 0, 1, false, j}, 60).torque ==
              Approx(90));
    }
    SECTION("too little torque: the impulse saturates at maxMotorTorque·dt")
    {
        j.maxMotorTorque = 3;
        SolverData data = rig.Data(MakeStep(kDt, false));
        InitVelocityConstraints(j, rig.a, rig.b, data);
        for (int i = 0; i < 8; ++i)
        {
            SolveVelocityConstraints(j, data);
        }
        CHECK(j.motorImpulse == Approx(3 * kDt));
        CHECK(rig.velocities[1].w == Approx(-1 + 2 * 3 * kDt));
    }
}

TEST_CASE("Revolute limits: speculative bias and one-sided impulses", "[joints][revolute]")
{
    // Wheel pinned at its centre (rB = 0), I = 1, so Δw = λ.
    Rig rig;
    rig.a = StaticBody();
    rig.b = DynamicBody(1, 1, 1, {0, 0});
    RevoluteJoint j;
    j.enableLimit = true;
    j.lowerAngle = Real(-0.5);
    j.upperAngle = Real(0.5);
    SolverData data = rig.Data(MakeStep(kDt, false));

    SECTION("approaching the lower limit: allowed to close exactly the gap this step")
    {
        rig.positions[1].a = Real(-0.49); // 0.01 rad above the lower limit
        rig.velocities[1].w = -5;
        InitVelocityConstraints(j, rig.a, rig.b, data);
        SolveVelocityConstraints(j, data);
        CHECK(rig.velocities[1].w == Approx(-0.01 * 60).margin(kVelocityTol));
        CHECK(j.lowerImpulse == Approx(5 - 0.6).margin(kVelocityTol));
        CHECK(j.upperImpulse == 0);
        CHECK(GetReaction(j, 60).torque == Approx(60 * 4.4).epsilon(1e-5));
    }
    SECTION("approaching the upper limit: positive impulse, negative torque on B")
    {
        rig.positions[1].a = Real(0.49);
        rig.velocities[1].w = 5;
        InitVelocityConstraints(j, rig.a, rig.b, data);
        SolveVelocityConstraints(j, data);
        CHECK(rig.velocities[1].w == Approx(0.6).margin(kVelocityTol));
        CHECK(j.upperImpulse == Approx(4.4).margin(kVelocityTol));
        CHECK(j.lowerImpulse == 0);
        CHECK(GetReaction(j, 60).torque == Approx(-60 * 4.4).epsilon(1e-5));
    }
    SECTION("moving away from a limit: the limit does not pull")
    {
        rig.positions[1].a = Real(-0.49);
        rig.velocities[1].w = 5;
        InitVelocityConstraints(j, rig.a, rig.b, data);
        SolveVelocityConstraints(j, data);
        CHECK(rig.velocities[1].w == Approx(5));
        CHECK(j.lowerImpulse == 0);
        CHECK(j.upperImpulse == 0);
    }
    SECTION("position pass: a violated limit is corrected by at most maxAngularCorrection")
    {
        const Tolerances tol;
        rig.positions[1].a = Real(-0.7); // 0.2 rad past the lower limit
        InitVelocityConstraints(j, rig.a, rig.b, data);
        CHECK_FALSE(SolvePositionConstraints(j, data));
        CHECK(rig.positions[1].a == Approx(-0.7 + tol.maxAngularCorrection).epsilon(1e-6));
        // Second call: the remaining 0.06 rad less the slop left in place. The error Box2D
        // reports is the corrected amount |C| = 0.026 ≤ angularSlop, so this call already
        // counts as solved although the limit is still violated by the slop.
        CHECK(SolvePositionConstraints(j, data));
        CHECK(rig.positions[1].a == Approx(-0.5 - tol.angularSlop).epsilon(1e-6));
        // At the slop boundary nothing more moves.
        CHECK(SolvePositionConstraints(j, data));
        CHECK(rig.positions[1].a == Approx(-0.5 - tol.angularSlop).epsilon(1e-6));
    }
    SECTION("position pass: limits closer than 2·angularSlop act as one equality row")
    {
        j.lowerAngle = Real(0.1);
        j.upperAngle = Real(0.11);
        rig.positions[1].a = Real(0.105);
        InitVelocityConstraints(j, rig.a, rig.b, data);
        SolvePositionConstraints(j, data);
        CHECK(rig.positions[1].a == Approx(0.1).epsilon(1e-6)); // pulled to the lower angle
    }
}

TEST_CASE("Revolute position pass closes an anchor gap, block and scalar rows",
          "[joints][revolute]")
{
    const bool block = GENERATE(true, false);
    CAPTURE(block);
    Pendulum p = MakePendulum({0, 0}, 0);
    p.rig.positions[1].c += Vec2(Real(0.1), Real(-0.05));
    SolverData data = p.rig.Data(MakeStep(kDt, false, block));
    InitVelocityConstraints(p.joint, p.rig.a, p.rig.b, data);

    const Real gap0 = WorldAnchor(p.rig, 1, kBarAnchor, kBarCenter).Length();
    REQUIRE(gap0 > Real(0.1));
    CHECK_FALSE(SolvePositionConstraints(p.joint, data)); // reports the error it started with
    const Real gap1 = WorldAnchor(p.rig, 1, kBarAnchor, kBarCenter).Length();
    // One linearised step: the block Newton step leaves only the second-order rotation error
    // (≈ r·Δθ²/2 with Δθ ≈ 0.08 rad: ≈ 3 mm); the scalar sweep leaves the rows' coupling too.
    CHECK(gap1 < (block ? Real(0.01) : Real(0.5) * gap0));

    bool solved = false;
    for (int i = 0; i < 20 && !solved; ++i)
    {
        solved = SolvePositionConstraints(p.joint, data);
    }
    CHECK(solved);
    const Tolerances tol;
    CHECK(WorldAnchor(p.rig, 1, kBarAnchor, kBarCenter).Length() <= tol.linearSlop);
}

TEST_CASE("A pendulum under gravity stays pinned, block and scalar rows", "[joints][revolute]")
{
    const bool block = GENERATE(true, false);
    CAPTURE(block);
    MiniWorld w = PendulumWorld();
    const StepContext step = MakeStep(kDt, true, block);
    Real maxGap = 0;
    for (int i = 0; i < 300; ++i)
    {
        StepWorld(w, step, {0, -10});
        maxGap = std::max(maxGap, AnchorGap(w, w.joints[0], {0, 0}, kBarAnchor).Length());
    }
    // The position pass stops once the gap is within the slop; a step's velocity error adds
    // less than that, so the gap never exceeds linearSlop.
    CHECK(maxGap <= step.tolerances.linearSlop);
    // The pendulum actually swung (it starts at rest 0.7 rad above the horizontal).
    CHECK(std::abs(w.positions[1].a - kBarAngle) > Real(0.5));
    // The reaction on the bar is finite and, summed with gravity, of the right order: the
    // pivot carries at most a few times the bar's weight.
    const JointReaction r = GetJointReaction(w.joints[0], step.invDt);
    CHECK(r.force.Length() < Real(60));
    CHECK(r.force.Length() > Real(1));
}

// ---------------------------------------------------------------------------------------------
// Reactions and dispatch

TEST_CASE("Joint reactions are the accumulated impulses times invDt", "[joints]")
{
    RevoluteJoint r;
    r.impulse = {Real(0.5), Real(-2)};
    r.motorImpulse = Real(0.25);
    r.lowerImpulse = Real(0.125);
    r.upperImpulse = Real(1);
    Joint jr{JointType::Revolute, 0, 1, false, r};
    const JointReaction rr = GetJointReaction(jr, 60);
    CHECK(rr.force == Vec2(30, -120));
    CHECK(rr.torque == Approx(60 * (0.25 + 0.125 - 1.0)));

    DistanceJoint d;
    d.u = {Real(0.6), Real(0.8)};
    d.impulse = Real(0.5);
    d.lowerImpulse = Real(0.25);
    d.upperImpulse = Real(0.125);
    Joint jd{JointType::Distance, 0, 1, false, d};
    const JointReaction dr = GetJointReaction(jd, 50);
    CHECK(dr.force.x == Approx(50 * 0.625 * 0.6));
    CHECK(dr.force.y == Approx(50 * 0.625 * 0.8));
    CHECK(dr.torque == 0);
}

// ---------------------------------------------------------------------------------------------
// Distance joint

namespace
{

/// Ground at the origin and a body hanging from it on a rod: the rod runs from the origin to
/// the body's anchor (0.2, 0) in body coordinates, centre of mass off the anchor so that
/// the row involves rotation.
MiniWorld RodWorld(Real length, Real angle)
{
    MiniWorld w;
    const Vec2 localCenter{0, Real(0.05)};
    w.bodies = {StaticBody(), DynamicBody(1, 2, Real(0.1), localCenter)};
    w.masses = {0, 2};
    w.positions.resize(2);
    w.velocities.resize(2);
    const Vec2 anchor = length * Vec2(std::sin(angle), -std::cos(angle));
    w.positions[1].c = CenterForAnchor(anchor, {Real(0.2), 0}, localCenter, Real(0.3));
    w.positions[1].a = Real(0.3);
    DistanceJointDef def;
    def.localAnchorB = {Real(0.2), 0};
    def.length = length;
    def.minLength = length;
    def.maxLength = length;
    w.joints.push_back(MakeJoint(def, 0, 1, 0, 2, Tolerances{}));
    return w;
}

Real RodLength(const MiniWorld& w)
{
    return AnchorGap(w, w.joints[0], {0, 0}, {Real(0.2), 0}).Length();
}

} // namespace

TEST_CASE("Distance rigid rod: one velocity solve removes the axial speed", "[joints][distance]")
{
    MiniWorld w = RodWorld(1, Real(0.9));
    w.velocities[1].v = {Real(1.5), Real(-2)};
    w.velocities[1].w = Real(4);
    SolverData data;
    data.step = MakeStep(kDt, false);
    data.positions = w.positions.data();
    data.velocities = w.velocities.data();
    Joint& joint = w.joints[0];
    InitJointVelocityConstraints(joint, w.bodies[0], w.bodies[1], data);
    const DistanceJoint& d = std::get<DistanceJoint>(joint.data);
    CHECK(d.u.Length() == Approx(1));
    CHECK(d.currentLength == Approx(1));
    // Seed: k = 1/m + (rB×u)²/I.
    const double crBu = double(d.rB.x) * d.u.y - double(d.rB.y) * d.u.x;
    CHECK(d.mass == Approx(1.0 / (0.5 + crBu * crBu / 0.1)).epsilon(1e-6));

    auto axialSpeed = [&]
    {
        const Velocity& B = w.velocities[1];
        return Dot(d.u, B.v + Cross(B.w, d.rB));
    };
    REQUIRE(std::abs(axialSpeed()) > Real(0.5));
    SolveJointVelocityConstraints(joint, data);
    CHECK(axialSpeed() == Approx(0).margin(kVelocityTol));
    // The impulse acts along u only: m·Δv = λ·u.
    CHECK(w.velocities[1].v.x - Real(1.5) == Approx(0.5 * d.impulse * d.u.x).margin(1e-6));
}

TEST_CASE("Distance rigid rod keeps its length under gravity thanks to the position pass",
          "[joints][distance]")
{
    MiniWorld w = RodWorld(Real(1.2), Real(1.2));
    StepContext step = MakeStep(kDt, true, true);
    Real maxError = 0;
    for (int i = 0; i < 240; ++i)
    {
        StepWorld(w, step, {0, -10});
        maxError = std::max(maxError, std::abs(RodLength(w) - Real(1.2)));
    }
    // The position pass exits once |C| < linearSlop.
    CHECK(maxError < step.tolerances.linearSlop);

    // Control: without position iterations the rod stretches (the velocity rows hold only
    // the length's rate at the start of each step, not the length).
    MiniWorld drift = RodWorld(Real(1.2), Real(1.2));
    step.solver.positionIterations = 0;
    for (int i = 0; i < 240; ++i)
    {
        StepWorld(drift, step, {0, -10});
    }
    CHECK(std::abs(RodLength(drift) - Real(1.2)) > 4 * step.tolerances.linearSlop);
}

TEST_CASE("Distance spring constants follow b2LinearStiffness", "[joints][distance]")
{
    DistanceJointDef def;
    def.minLength = Real(0.5);
    def.maxLength = 2;
    def.hertz = 3;
    def.dampingRatio = Real(0.4);
    const double omega = 2 * 3.14159265358979 * 3;

    SECTION("against static ground the oscillator mass is the body's mass")
    {
        const Joint j = MakeJoint(def, 0, 1, 0, 2, Tolerances{});
        const DistanceJoint& d = std::get<DistanceJoint>(j.data);
        CHECK(d.stiffness == Approx(2 * omega * omega).epsilon(1e-6));
        CHECK(d.damping == Approx(2 * 2 * 0.4 * omega).epsilon(1e-6));
    }
    SECTION("in b2LinearStiffness's float operation order: (m·ω)·ω and ((2·m)·ζ)·ω")
    {
        // Inputs for which other orders round differently (e.g. 2·m·ω·ζ, m·(ω·ω)).
        def.hertz = Real(1.7);
        def.dampingRatio = Real(0.4);
        const Joint j = MakeJoint(def, 0, 1, 3, 0, Tolerances{});
        const DistanceJoint& d = std::get<DistanceJoint>(j.data);
        const Real w = Real(2) * kPi * Real(1.7);
        CHECK(d.stiffness == Real(3) * w * w);
        CHECK(d.damping == Real(2) * Real(3) * Real(0.4) * w);
    }
    SECTION("static body as B works the same")
    {
        const Joint j = MakeJoint(def, 0, 1, 2, 0, Tolerances{});
        CHECK(std::get<DistanceJoint>(j.data).stiffness == Approx(2 * omega * omega));
    }
    SECTION("two dynamic bodies use the reduced mass mA·mB/(mA + mB)")
    {
        const Joint j = MakeJoint(def, 0, 1, 2, 6, Tolerances{});
        CHECK(std::get<DistanceJoint>(j.data).stiffness ==
              Approx(1.5 * omega * omega).epsilon(1e-6));
    }
    SECTION("no spring without a frequency")
    {
        def.hertz = 0;
        const Joint j = MakeJoint(def, 0, 1, 0, 2, Tolerances{});
        CHECK(std::get<DistanceJoint>(j.data).stiffness == 0);
        CHECK(std::get<DistanceJoint>(j.data).damping == 0);
    }
}

TEST_CASE("Distance spring oscillates at its frequency", "[joints][distance]")
{
    // A 2 kg body on a 1 Hz undamped spring to static ground, no gravity, stretched 0.1 m.
    MiniWorld w;
    w.bodies = {StaticBody(), DynamicBody(1, 2, 1, {0, 0})};
    w.masses = {0, 2};
    w.positions.resize(2);
    w.velocities.resize(2);
    w.positions[1].c = {Real(1.1), 0};
    DistanceJointDef def;
    def.length = 1;
    def.hertz = 1;
    w.joints.push_back(MakeJoint(def, 0, 1, 0, 2, Tolerances{}));

    const Real dt = Real(1) / Real(240);
    const StepContext step = MakeStep(dt);
    std::vector<double> upCrossings;
    Real previous = Real(0.1);
    for (int i = 1; i <= 240 * 3; ++i)
    {
        StepWorld(w, step, {0, 0});
        const Real x = w.positions[1].c.x - 1;
        if (previous < 0 && x >= 0)
        {
            upCrossings.push_back((i - 1 + previous / (previous - x)) * dt);
        }
        previous = x;
    }
    REQUIRE(upCrossings.size() >= 2);
    // Implicit Euler shifts the frequency by O((ωh)²) ≈ 7e-4: 1 % is generous, while a wrong
    // stiffness (e.g. the mass dropped or ω not squared) misses by far more.
    CHECK(upCrossings[1] - upCrossings[0] == Approx(1.0).epsilon(0.01));
    // Implicit Euler also loses energy, but slowly at 240 Hz: still oscillating.
    CHECK(std::abs(w.positions[1].c.x - 1) < Real(0.1));
}

TEST_CASE("Distance limits act as a rope and a strut", "[joints][distance]")
{
    // Body of 1 kg, anchors at the centres: k = 1/m = 1, so Δv along u = λ.
    Rig rig;
    rig.a = StaticBody();
    rig.b = DynamicBody(1, 1, 1, {0, 0});
    DistanceJoint d;
    d.minLength = Real(0.5);
    d.maxLength = 2;
    SolverData data = rig.Data(MakeStep(kDt, false));

    SECTION("near the upper limit and moving out: the speed closes the gap exactly")
    {
        rig.positions[1].c = {Real(1.99), 0};
        rig.velocities[1].v = {3, 1};
        InitVelocityConstraints(d, rig.a, rig.b, data);
        SolveVelocityConstraints(d, data);
        CHECK(rig.velocities[1].v.x == Approx(0.01 * 60).margin(kVelocityTol));
        CHECK(rig.velocities[1].v.y == 1); // across the rope: free
        CHECK(d.upperImpulse == Approx(3 - 0.6).margin(kVelocityTol));
        CHECK(d.lowerImpulse == 0);
        CHECK(d.impulse == 0); // no spring, and not rigid: the rest length is not held
        CHECK(GetReaction(d, 60).force.x == Approx(-60 * 2.4).epsilon(1e-5));
    }
    SECTION("inside the limits without a spring nothing acts")
    {
        rig.positions[1].c = {1, 0};
        rig.velocities[1].v = {3, 1};
        InitVelocityConstraints(d, rig.a, rig.b, data);
        SolveVelocityConstraints(d, data);
        CHECK(rig.velocities[1].v == Vec2(3, 1));
        CHECK(SolvePositionConstraints(d, data));
    }
    SECTION("past the lower limit the position pass pushes out by the full error")
    {
        rig.positions[1].c = {Real(0.3), 0};
        InitVelocityConstraints(d, rig.a, rig.b, data);
        CHECK_FALSE(SolvePositionConstraints(d, data));
        CHECK(rig.positions[1].c.x == Approx(0.5).epsilon(1e-6));
        CHECK(SolvePositionConstraints(d, data));
    }
    SECTION("a rigid rod's position error is corrected in full, without a clamp")
    {
        // 2.4.1 dropped the maxLinearCorrection (0.2 m) clamp of earlier versions.
        d.length = d.minLength = d.maxLength = 1;
        rig.positions[1].c = {Real(1.5), 0};
        InitVelocityConstraints(d, rig.a, rig.b, data);
        CHECK_FALSE(SolvePositionConstraints(d, data));
        CHECK(rig.positions[1].c.x == Approx(1).epsilon(1e-6));
        CHECK(SolvePositionConstraints(d, data));
    }
    SECTION("warm start applies (impulse + lower − upper)·u")
    {
        rig.positions[1].c = {Real(1.5), 0};
        d.impulse = Real(0.5);
        d.lowerImpulse = Real(0.25);
        d.upperImpulse = 1;
        data.step.solver.warmStarting = true;
        InitVelocityConstraints(d, rig.a, rig.b, data);
        CHECK(rig.velocities[1].v.x == Approx(-0.25));
        CHECK(rig.velocities[1].v.y == 0);
    }
}

TEST_CASE("Distance rows vanish when the anchors coincide", "[joints][distance]")
{
    Rig rig;
    rig.a = StaticBody();
    rig.b = DynamicBody(1, 1, 1, {0, 0});
    rig.velocities[1].v = {1, 2};
    DistanceJoint d;
    d.minLength = d.maxLength = d.length = 1;
    d.impulse = 5;
    SolverData data = rig.Data(MakeStep(kDt, true));
    InitVelocityConstraints(d, rig.a, rig.b, data);
    CHECK(d.u == Vec2(0, 0));
    CHECK(d.impulse == 0);
    SolveVelocityConstraints(d, data);
    CHECK(rig.velocities[1].v == Vec2(1, 2));
}

// ---------------------------------------------------------------------------------------------
// MakeJoint

TEST_CASE("MakeJoint copies a revolute definition", "[joints][make]")
{
    RevoluteJointDef def;
    def.localAnchorA = {1, 2};
    def.localAnchorB = {3, 4};
    def.referenceAngle = Real(0.25);
    def.enableLimit = true;
    def.lowerAngle = Real(-0.5);
    def.upperAngle = Real(-0.5); // equal limits are allowed
    def.enableMotor = true;
    def.motorSpeed = -3;
    def.maxMotorTorque = 7;
    def.collideConnected = true;
    const Joint j = MakeJoint(def, 4, 9);
    CHECK(j.type == JointType::Revolute);
    CHECK(j.bodyA == 4);
    CHECK(j.bodyB == 9);
    CHECK(j.collideConnected);
    const RevoluteJoint& r = std::get<RevoluteJoint>(j.data);
    CHECK(r.localAnchorA == Vec2(1, 2));
    CHECK(r.localAnchorB == Vec2(3, 4));
    CHECK(r.referenceAngle == Real(0.25));
    CHECK(r.enableLimit);
    CHECK(r.lowerAngle == Real(-0.5));
    CHECK(r.enableMotor);
    CHECK(r.motorSpeed == -3);
    CHECK(r.maxMotorTorque == 7);
    CHECK(r.impulse == Vec2(0, 0));
}

TEST_CASE("MakeJoint clamps distance lengths as Box2D's constructor", "[joints][make]")
{
    Tolerances tol;
    tol.linearSlop = Real(0.01);
    DistanceJointDef def;
    def.length = -1;
    def.minLength = 0;
    def.maxLength = Real(0.001);
    const Joint j = MakeJoint(def, 0, 1, 0, 1, tol);
    CHECK(j.type == JointType::Distance);
    const DistanceJoint& d = std::get<DistanceJoint>(j.data);
    CHECK(d.length == Real(0.01));
    CHECK(d.minLength == Real(0.01));
    CHECK(d.maxLength == Real(0.01)); // raised to the clamped minimum: now a rigid rod
}

TEST_CASE("MakeJoint rejects bad definitions", "[joints][make]")
{
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real inf = std::numeric_limits<Real>::infinity();

    SECTION("revolute")
    {
        RevoluteJointDef def;
        SECTION("non-finite anchor")
        {
            def.localAnchorB = {nan, 0};
            MEFF_CHECK_ERROR(MakeJoint(def, 0, 1));
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1), Catch::Contains("localAnchorB"));
        }
        SECTION("non-finite angles and speeds")
        {
            def.referenceAngle = inf;
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1), Catch::Contains("referenceAngle"));
            def.referenceAngle = 0;
            def.lowerAngle = -inf;
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1), Catch::Contains("lowerAngle"));
            def.lowerAngle = 0;
            def.motorSpeed = nan;
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1), Catch::Contains("motorSpeed"));
        }
        SECTION("negative motor torque")
        {
            def.maxMotorTorque = -1;
            MEFF_CHECK_ERROR(MakeJoint(def, 0, 1));
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1),
                                  Catch::Contains("maxMotorTorque") && Catch::Contains("-1"));
        }
        SECTION("lowerAngle above upperAngle")
        {
            def.lowerAngle = 1;
            def.upperAngle = Real(0.5);
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1),
                                  Catch::Equals("RevoluteJointDef::lowerAngle: must not exceed "
                                                "upperAngle (0.5), got 1"));
        }
    }
    SECTION("distance")
    {
        DistanceJointDef def;
        const Tolerances tol;
        SECTION("non-finite anchor or length")
        {
            def.localAnchorA = {0, inf};
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, tol), Catch::Contains("localAnchorA"));
            def.localAnchorA = {0, 0};
            def.length = nan;
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, tol), Catch::Contains("length"));
            def.length = 1;
            def.maxLength = inf;
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, tol), Catch::Contains("maxLength"));
        }
        SECTION("minLength above maxLength")
        {
            def.minLength = 2;
            def.maxLength = 1;
            MEFF_CHECK_ERROR(MakeJoint(def, 0, 1, 0, 1, tol));
            MEFF_CHECK_ERROR_WITH(
                MakeJoint(def, 0, 1, 0, 1, tol),
                Catch::Equals("DistanceJointDef::minLength: must not exceed maxLength (1), got 2"));
        }
        SECTION("negative or non-finite spring parameters")
        {
            def.hertz = -1;
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, tol), Catch::Contains("hertz"));
            def.hertz = 1;
            def.dampingRatio = Real(-0.1);
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, tol), Catch::Contains("dampingRatio"));
            def.dampingRatio = nan;
            MEFF_CHECK_ERROR_WITH(MakeJoint(def, 0, 1, 0, 1, tol), Catch::Contains("dampingRatio"));
        }
        SECTION("the defaults are accepted")
        {
            MEFF_CHECK_NO_ERROR(MakeJoint(def, 0, 1, 0, 1, tol));
        }
    }
}
