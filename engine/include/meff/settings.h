// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// How a world is made and stepped: WorldDef, the solver back ends and their settings, the
// tolerances. Plain data: a game can keep and edit these without including the World.
#pragma once

#include "meff/math.h"

namespace meff
{

/// Tolerances of the solver, collision and sleeping. Defaults are Box2D 2.4.1's constants.
struct Tolerances
{
    Real linearSlop = Real(0.005);        ///< allowed penetration / joint error (m)
    Real polygonSkin = Real(0.01);        ///< radius added to polygons and segments (m)
    Real aabbMargin = Real(0.1);          ///< fattening of broad-phase boxes (m)
    Real maxLinearCorrection = Real(0.2); ///< largest position correction per iteration (m)
    Real maxAngularCorrection = Real(8) / Real(180) * kPi; ///< rad
    Real angularSlop = Real(2) / Real(180) * kPi;          ///< rad
    Real maxTranslation = 2;            ///< largest move of a body in one step (m)
    Real maxRotation = Real(0.5) * kPi; ///< largest turn of a body in one step (rad)
    Real baumgarte = Real(0.2);         ///< fraction of overlap removed per position iteration
    /// Fraction of overlap removed per position iteration of a time-of-impact sub-step.
    Real toiBaumgarte = Real(0.75);
    /// Sleeping (when WorldDef::allowSleep): a body whose speeds stay within both sleep
    /// tolerances accumulates rest time; an island whose every body has rested this long falls
    /// asleep together (Box2D 2.4.1's b2_timeToSleep, b2_linearSleepTolerance,
    /// b2_angularSleepTolerance).
    Real timeToSleep = Real(0.5);                           ///< s
    Real linearSleepTolerance = Real(0.01);                 ///< m/s
    Real angularSleepTolerance = Real(2) / Real(180) * kPi; ///< rad/s
    /// Smallest approach speed that makes a contact hit event (m/s; Box2D v3's
    /// hitEventThreshold). A speed, but in length units per second, so it scales with them.
    Real hitEventThreshold = 1;

    /// Every member equal.
    friend bool operator==(const Tolerances&, const Tolerances&) = default;
};

/// Tolerances for a world measured in `lengthUnitsPerMeter` units per metre (32 for a game
/// that works in pixels at 32 px/m, say): every length tolerance — slop, skin, broad-phase
/// margin, maximum correction, maximum translation, linear sleep tolerance, the hit-event
/// speed — scales together; angles and times do not. Throws
/// InvalidArgument unless the scale is finite and > 0. Gravity, sizes, speeds and each shape's
/// restitution threshold (m/s) are yours to give in the same units.
Tolerances TolerancesForLengthUnits(Real lengthUnitsPerMeter);

/// Which solver back end steps the world (SolverSettings::kind). Each is one way of trading
/// speed for accuracy; all solve every constraint row with the scalar effective mass
/// 1/k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB (docs/effective-mass.md).
enum class SolverKind
{
    /// Box2D 2.4.1's step: velocityIterations sequential-impulse sweeps in island order, then
    /// positionIterations non-linear Gauss-Seidel sweeps. Bit-identical to Box2D 2.4.1.
    Box2D,
    /// The same rows, effective masses, iteration counts, block solvers and position pass as
    /// Box2D, visited colour by colour (Box2D v3's graph colouring): an island's contacts, and
    /// apart from them its revolute joints without limit, motor or spring (with blockJoints on),
    /// are sorted into colours that share no moving body, and each colour is solved four
    /// constraints at a time in SIMD lanes (eight in a MEFF_AVX2 build). Another Gauss-Seidel
    /// order, so results agree with Box2D 2.4.1 only up to that order's effect (settled-state
    /// checks), not bit for bit. Other joints keep the island order after the lanes. Without sleep
    /// (WorldDef::allowSleep off) and with every moving body awake, the whole world is solved as
    /// one island, gathered from the arrays instead of searched: the position pass then stops when
    /// the whole world is within tolerance, not island by island. A moving body kept asleep
    /// (BodyDef::awake false, SetAwake(false)) brings back the island search.
    Colour,
    /// Sub-stepped soft constraints (SoftStepSettings): each step is cut into `substeps`
    /// sub-steps integrated as velocity Verlet; in each, velocities are integrated, last
    /// impulses applied, every row solved once with a soft position bias, positions integrated,
    /// contacts corrected and the rows relaxed without bias. Far more accurate for joints
    /// (pendulums, chains, ragdolls) than Box2D's step at about its cost, as stiff for stacks;
    /// see docs/performance.md for the measured trade.
    SoftStep,
};

/// How the soft step holds contacts (SoftStepSettings::contacts).
enum class SoftContactModel
{
    /// Rigid velocity rows (two-point manifolds as a 2×2 block with SolverSettings::blockSolver)
    /// and, after each sub-step's move, a position correction that removes contactCorrection of
    /// the overlap beyond linearSlop without giving the bodies velocity: stacks do not sag
    /// under their load and overlapping bodies separate gently.
    Rigid,
    /// Box2D v3's soft rows: the overlap is pushed out by a spring of contactHertz and
    /// contactDampingRatio. Each point sinks in proportion to the load it carries, so stacks
    /// sag (docs/soft-step.md).
    Soft,
};

/// The sub-stepped soft solver (SolverKind::SoftStep). Each step is cut into `substeps`
/// sub-steps of h = dt/substeps, integrated as velocity Verlet. A soft row drives its position
/// error C to zero as a damped spring of natural frequency `hertz` and damping ratio ζ would,
/// solved implicitly over h (docs/soft-step.md derives the coefficients from the effective
/// mass). Every member may be changed between steps.
struct SoftStepSettings
{
    int substeps = 4; ///< sub-steps per step, ≥ 1
    /// Relax sweeps per sub-step (≥ 0): every row solved again rigidly, without position bias,
    /// which takes back the velocity the bias added. Friction is solved in these sweeps (in the
    /// biased sweep when there are none).
    int relaxIterations = 1;
    SoftContactModel contacts = SoftContactModel::Rigid; ///< rigid or soft contacts
    /// Rigid contacts: fraction of the overlap beyond linearSlop removed per sub-step, in (0, 1].
    Real contactCorrection = Real(0.1);
    /// Soft contacts: stiffness (Hz, > 0) and damping ratio (≥ 0). The stiffness is capped at a
    /// quarter of the sub-step rate, and doubled against a body that cannot move.
    Real contactHertz = 30;
    Real contactDampingRatio = 10; ///< soft contacts' damping ratio (≥ 0)
    /// Largest speed (m/s, > 0) of the soft contacts' push-out, of a rigid contact's correction
    /// (× h per sub-step) and of a joint's gap closed by velocity (beyond it: bodies moved).
    Real maxPushOutSpeed = 3;
    /// Stiffness (Hz, > 0) and damping ratio (≥ 0) of the joints' rigid rows (points, angles,
    /// limits) while solving, capped at 0.3 of the sub-step rate (72 Hz at 60 Hz × 4).
    Real jointHertz = 72;
    Real jointDampingRatio = 0; ///< the joints' rows' damping ratio (≥ 0)
    /// Solve the point rows of revolute joints that join bodies as a tree (a chain, a ragdoll,
    /// hanging from at most one fixed pivot) together, exactly, rather than joint by joint: a
    /// load then passes through the whole tree at once, so light links holding a heavy body do
    /// not stretch (docs/soft-step.md, "Joint trees").
    bool jointTrees = true;

    /// Every member equal.
    friend bool operator==(const SoftStepSettings&, const SoftStepSettings&) = default;
};

/// How the solver works. Every member may be changed between steps.
struct SolverSettings
{
    SolverKind kind = SolverKind::Box2D; ///< the back end (see SolverKind)
    int velocityIterations = 8; ///< Box2D, Colour: sequential-impulse sweeps per step, ≥ 1
    int positionIterations = 3; ///< Box2D, Colour: non-linear Gauss-Seidel sweeps per step, ≥ 0
    bool warmStarting = true;   ///< start each step (sub-step) from last step's impulses
    /// Box2D, Colour: solve a two-point manifold's normal rows together as a 2×2 block
    /// (Box2D's block solver). Off: every row alone with its scalar effective mass.
    bool blockSolver = true;
    /// Solve a joint's coupled rows as one block (Box2D): the revolute and mouse point (2×2),
    /// the prismatic's perpendicular and angular rows (2×2, with its axial limit row in the
    /// position pass when active), the weld's point and angle (3×3; 2×2 point when soft), the
    /// motor's linear part (2×2). Off: each row alone with its scalar effective mass.
    bool blockJoints = true;
    /// Where restitution's approach speed vn is measured (the bounce targets −e·vn).
    /// Off (Box2D 2.4.1): after this step's gravity was added, so every bounce returns g·dt
    /// more speed than arrived and e = 1 gains energy bounce after bounce. On: at the start of
    /// the step, so restitution never adds energy (results then differ from Box2D's).
    /// SoftStep always measures it before the first sub-step.
    bool restitutionFromStepStart = false;
    SoftStepSettings softStep{}; ///< SoftStep only

    /// Every member equal.
    friend bool operator==(const SolverSettings&, const SolverSettings&) = default;
};

/// The name of a solver back end as scene files and the tools write it: "box2d", "colour",
/// "soft_step".
const char* SolverKindName(SolverKind kind);

/// Everything needed to create a world.
struct WorldDef
{
    Vec2 gravity{0, -10};    ///< m/s²
    SolverSettings solver{}; ///< the back end and its settings
    Tolerances tolerances{}; ///< Box2D's constants (see TolerancesForLengthUnits)
    /// Let resting islands fall asleep (Box2D 2.4.1's rules, see Tolerances::timeToSleep): a
    /// sleeping body is not integrated, solved, collided or moved in the broad phase until
    /// something wakes it. On by default, as in Box2D 2.4.1 and v3; `false` keeps every body
    /// awake (what a step-by-step comparison with a Box2D world that never sleeps needs).
    /// World::SetAllowSleeping changes it later. Scene files keep their own default (off).
    bool allowSleep = true;
    /// Continuous collision (Box2D's continuous physics, on by default there too): after each
    /// step, fast dynamic bodies are moved back to their first time of impact with static and
    /// kinematic shapes (bullets: with dynamic shapes too) and re-solved over the rest of the
    /// step, so they do not tunnel through thin geometry. Off: only the discrete step runs,
    /// and a body that moves further than a shape's thickness in one step can pass through it.
    /// Whatever the solver back end, the time-of-impact sub-steps are Box2D 2.4.1's (its
    /// position pass on the pair, then its velocity sweeps in island order).
    bool continuous = true;
};

} // namespace meff
