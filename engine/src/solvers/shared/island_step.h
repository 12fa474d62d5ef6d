// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Box2D 2.4.1's step of one island (b2Island::Solve), with the contact rows and the joint rows
// as stages: the Box2D back end passes its island-order solvers (ContactSolver, JointSolver),
// the colour back end its lanes (colour/), and the step is the same:
//
//   integrate velocities → prepare contacts → warm start contacts → prepare joints (with their
//   warm start) → velocity sweeps (joints, then contacts) → store impulses → integrate
//   positions → correct positions (contacts, then joints; stop once within tolerance) → finish
//   bodies → report solved contacts → sleep
#pragma once

#include "model/solver_types.h"
#include "solvers/shared/contact_constraint.h"
#include "solvers/shared/island.h"
#include "solvers/solver.h"
#include "meff/function_ref.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace meff::detail
{

struct Contact;
struct JointSlot;

/// The contact rows of one island (ContactSolver in island order, ColourContactSolver by colour).
class ContactStage
{
  public:
    /// What Prepare needs of the island alone, not of its velocities (the colour back end's
    /// colouring): SolveIsland runs it on one thread, perhaps a pool thread, while the others
    /// integrate the velocities (IntegrateVelocities' `beside`). Bodies' islandIndex must be set;
    /// `bodyCount` is the island's.
    virtual void Arrange(const IslandContacts& island, std::size_t bodyCount)
    {
        static_cast<void>(island);
        static_cast<void>(bodyCount);
    }
    /// Builds the rows of the island's contacts, after Arrange. Bodies' islandIndex must be set.
    virtual void Prepare(const IslandContacts& island, SolverData& data) = 0;
    /// Applies last step's accumulated impulses (scaled in Prepare).
    virtual void WarmStart(SolverData& data) = 0;
    /// One velocity sweep: each contact's friction rows, then its normal rows.
    virtual void SolveVelocities(SolverData& data) = 0;
    /// Gathers what the rest of the step reads of the solved contacts into SolvedContacts().
    virtual void CollectResults() = 0;
    /// One non-linear Gauss-Seidel sweep; true when no point overlaps more than 3·slop.
    virtual bool SolvePositions(SolverData& data) = 0;
    /// The island's contacts in island order, after CollectResults.
    virtual std::span<const SolvedContact> SolvedContacts() const = 0;
    /// Whether any of the island's contacts has a shape that asked for hit events.
    virtual bool AnyHitEvents() const = 0;

  protected:
    ~ContactStage() = default;
};

/// The joint rows of one island (JointSolver in island order, ColourJointSolver by colour).
class JointStage
{
  public:
    /// Prepares the island's joints and applies their warm start (InitVelocityConstraints).
    /// Bodies' islandIndex must be set.
    virtual void Prepare(std::span<const std::int32_t> jointIndices, std::span<JointSlot> joints,
                         std::span<const Body> bodies, SolverData& data) = 0;
    /// One velocity sweep.
    virtual void SolveVelocities(SolverData& data) = 0;
    /// Leaves every joint's accumulated impulses in the joint (reactions, next warm start).
    virtual void StoreImpulses() = 0;
    /// One non-linear Gauss-Seidel sweep; true when every joint is within tolerance.
    virtual bool SolvePositions(SolverData& data) = 0;

  protected:
    ~JointStage() = default;
};

/// Solves one island for one step with the given contact and joint stages.
void SolveIsland(SolverWorld& world, Island& island, const StepContext& step,
                 ContactStage& contacts, JointStage& joints);

/// Copies the island's bodies into island.positions/velocities (a slot more per worker of
/// world.tasks for the lanes' discard, SolverData::discardIndex) and adds gravity, forces and
/// damping to the velocities, bodies spread over world.tasks; `beside` runs meanwhile on one of
/// them (ForRangesBeside), so it must not touch the island's positions and velocities nor the
/// bodies' sweeps (which IntegrateVelocity writes), must not write any body field
/// IntegrateVelocity reads, and must not hand work to world.tasks.
void IntegrateVelocities(SolverWorld& world, Island& island, const StepContext& step,
                         FunctionRef<void()> beside);
/// Moves every body of the island by h·v (its motion clamped to Tolerances::maxTranslation
/// and maxRotation per step), bodies spread over `tasks` (null: the calling thread alone).
void IntegratePositions(Island& island, const StepContext& step, TaskSystem* tasks = nullptr);
/// Writes each solved contact's accumulated impulses into its manifold (next step's warm
/// start), contacts spread over `tasks` (null: the calling thread alone).
void StoreContactImpulses(std::span<const SolvedContact> solved, std::span<Contact> contacts,
                          TaskSystem* tasks = nullptr);

} // namespace meff::detail
