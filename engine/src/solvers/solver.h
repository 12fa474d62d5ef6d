// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The seam between the world's step and its solver back ends (SolverKind). World::Step runs
// the stages every back end shares — find new contacts, the narrow phase, synchronize the broad
// phase, continuous collision — and hands the solving of the awake bodies to the back end the
// settings choose. A back end lives in its own folder (box2d/, colour/, soft_step/) and owns its
// integration, its rows and its scratch memory; what it may read and write of the world is
// SolverWorld, and the contacts it solved it hands back through SolvedContactSink. What several
// back ends use lives beside them, never in one of them: shared/ (islands, Box2D's island step
// with its contact and joint stages, the rigid contact rows, the solved-contact records, joints
// one by one) and lanes/ (SIMD lanes, graph colouring, colour groups). No back end includes
// another's folder. The shared stages ask the back end's CollisionPolicy (Collision below), never
// which back end runs.
#pragma once

#include "collision/collision_policy.h"
#include "model/solver_types.h"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace meff::detail
{

struct Body;
struct Contact;
struct JointSlot;
struct SolvedContact;

/// Where a back end hands the contacts it has just solved (an island, or a time-of-impact
/// sub-step): the world records them for the contact reports and turns them into hit events.
class SolvedContactSink
{
  public:
    /// `anyHitEvents`: whether any of them has a shape that asked for hit events.
    virtual void Record(std::span<const SolvedContact> solved, bool anyHitEvents,
                        const StepContext& step) = 0;

  protected:
    ~SolvedContactSink() = default;
};

/// What a back end reads and writes of the world in one step.
struct SolverWorld
{
    /// Read: mass, damping, forces, state, sleep flags. Written: centre of mass, angle,
    /// transform and velocities of the bodies it solved, their sweeps' start (c0, a0), island
    /// flags and solver indices, rest times and sleep.
    std::vector<Body>& bodies;
    /// Read: manifolds, materials and flags of touching contacts. Written: the manifold
    /// points' accumulated impulses (next step's warm start) and island flags.
    std::vector<Contact>& contacts;
    /// Read: definitions. Written: accumulated impulses, solver temporaries, island flags.
    std::vector<JointSlot>& joints;
    std::int32_t bodyList; ///< newest first: the order the island search takes its seeds in
    Vec2 gravity;          ///< m/s²
    bool allowSleep;
    std::uint64_t stepCount; ///< steps taken so far, for error messages
    SolvedContactSink& solvedContacts;
    /// The world's threads (World::SetTaskSystem), or null. The Box2D back end steps without
    /// them (Box2DSolver::Step).
    TaskSystem* tasks = nullptr;
    /// Set when a body became non-finite (FinishBodies): in an engine without exceptions the
    /// step stops there, as a thrown SimulationError stops it (null: nowhere to set it).
    bool* failed = nullptr;
};

/// One solver back end.
class Solver
{
  public:
    virtual ~Solver() = default;
    /// Advances every awake body by one step: integrates forces and gravity, solves contacts
    /// and joints, writes the bodies back (reporting SimulationError, with the bodies left at
    /// their last good state, when one became non-finite: thrown, or without exceptions handed to
    /// the error handler with SolverWorld::failed set), reports the solved contacts, and
    /// with allowSleep puts resting islands to sleep. Sets Body::islandFlag on every body it
    /// moved, which the broad-phase synchronization reads.
    virtual void Step(SolverWorld& world, const StepContext& step) = 0;
    /// How the shared broad and narrow phases should work for this back end (the fat boxes,
    /// manifold recycling, the tree update): Box2DCollision or ThroughputCollision.
    virtual CollisionPolicy Collision(const Tolerances& tolerances) const = 0;
};

/// Box2D 2.4.1's collision: fat boxes of tolerances.aabbMargin stretched four times the step's
/// displacement, every manifold computed every step. The Box2D back end's, which must stay bit
/// for bit Box2D's.
CollisionPolicy Box2DCollision(const Tolerances& tolerances);

/// Collision for throughput (the colour and soft-step back ends), as Box2D v3's: fat boxes
/// with half of tolerances.aabbMargin (v3's 5 cm at the default 10 cm) and no stretch along the
/// motion, around the shape's end pose unless continuous collision needs its swept box; the tree
/// grown in place and its grown part built again each step instead of leaves re-inserted
/// (TreeUpdate::EnlargeAndRebuild); touching manifolds kept while their shapes move less than the
/// linear slop relative to each other (Collide). Against Box2D's rule: fewer candidate pairs, so
/// fewer contacts to walk and solve (spinner 127,000 → 34,000 by the soft step), and cheap tree
/// updates for the proxies that leave their smaller boxes more often (docs/performance.md). Which
/// contacts exist, and so their order, changes; a kept manifold is within the slop of the exact
/// one.
CollisionPolicy ThroughputCollision(const Tolerances& tolerances);

/// The world's back ends, each made when first used (a world pays for the one it runs).
/// Copying a world (a snapshot) does not copy them: they hold only memory that every step
/// rebuilds, so a copy starts with none.
class SolverSet
{
  public:
    SolverSet();
    ~SolverSet();
    SolverSet(const SolverSet&);
    SolverSet& operator=(const SolverSet&);
    SolverSet(SolverSet&&) noexcept;
    SolverSet& operator=(SolverSet&&) noexcept;

    Solver& For(SolverKind kind);

  private:
    std::unique_ptr<Solver> m_solvers[3]; ///< by SolverKind
};

} // namespace meff::detail
