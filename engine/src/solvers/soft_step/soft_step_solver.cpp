// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/soft_step/soft_step_solver.h"

#include "joints/joint_slot.h"
#include "model/body.h"
#include "solvers/shared/sequential_joints.h"
#include "tasks/parallel_ranges.h"

#include <algorithm>
#include <cmath>

namespace meff::detail
{

namespace
{

/// Whether a sweep changed any body's velocity by more than kSoftRelaxTolerance.
bool Changed(const std::vector<Velocity>& before, const std::vector<Velocity>& after)
{
    for (std::size_t i = 0; i < before.size(); ++i)
    {
        const Velocity& a = before[i];
        const Velocity& b = after[i];
        if (std::abs(a.v.x - b.v.x) > kSoftRelaxTolerance ||
            std::abs(a.v.y - b.v.y) > kSoftRelaxTolerance ||
            std::abs(a.w - b.w) > kSoftRelaxTolerance)
        {
            return true;
        }
    }
    return false;
}

} // namespace

SoftStepContext MakeSoftStepContext(const StepContext& step)
{
    const SoftStepSettings& settings = step.solver.softStep;
    SoftStepContext context;
    context.step = &step;
    context.substeps = settings.substeps;
    context.h = step.dt / Real(settings.substeps);
    context.invH = Real(settings.substeps) * step.invDt;
    // A contact spring stiffer than a quarter of the sub-step rate rings instead of settling
    // (Box2D v3's cap). Joints take up to 0.3 of it: chain20 starts to whip apart from about
    // 0.31 and joint_grid's net from 0.36, and the stiffer the joints the less a pendulum
    // loses (docs/soft-step.md).
    const Real maxHertz = Real(0.25) * context.invH;
    const Real maxJointHertz = Real(0.3) * context.invH;
    const Real contactHertz = Min(settings.contactHertz, maxHertz);
    context.contact = MakeSoft(contactHertz, settings.contactDampingRatio, context.h);
    context.staticContact =
        MakeSoft(Real(2) * contactHertz, settings.contactDampingRatio, context.h);
    // A joint closes its gap by velocity at most at the push-out speed, as a contact pushes
    // out; beyond that the joints' position pass (CorrectJoints) moves the bodies, so a
    // violated joint's gap never becomes motion (docs/soft-step.md, "Joints").
    context.joint =
        MakeSoft(Min(settings.jointHertz, maxJointHertz), settings.jointDampingRatio, context.h);
    context.joint.maxBias = settings.maxPushOutSpeed;
    context.jointCorrection = {context.joint.biasScale, 1, 0, context.joint.maxBias, true};
    context.maxPushOut = settings.maxPushOutSpeed;
    context.contactModel = settings.contacts;
    context.contactCorrection = settings.contactCorrection;
    context.rowSlop =
        settings.contacts == SoftContactModel::Rigid ? Real(0) : step.tolerances.linearSlop;
    context.blockSolver = step.solver.blockSolver;
    context.frictionInSolve = settings.relaxIterations == 0;
    return context;
}

void SoftStepSolver::Step(SolverWorld& world, const StepContext& step)
{
    m_context = MakeSoftStepContext(step);
    m_context.bodies = &m_bodies;
    m_context.tasks = world.tasks; // the threads GatherSoftBodies makes discard slots for
    const auto solve = [&](Island& island) { SolveIsland(world, island, step); };
    // Without sleep, islands would only split the work.
    if (!world.allowSleep && BuildWorldIsland(world, m_island))
    {
        solve(m_island);
        return;
    }
    ForEachAwakeIsland(world, m_island, solve);
}

void SoftStepSolver::SolveIsland(SolverWorld& world, Island& island, const StepContext& step)
{
    GatherSoftBodies(world, island, m_context.h, m_bodies);
    // Stored impulses are per step (as the other back ends store them); the rows work per
    // sub-step.
    const Real warmScale =
        step.solver.warmStarting ? step.dtRatio / Real(m_context.substeps) : Real(0);
    m_contacts.Prepare({island.contacts, world.contacts, world.bodies}, m_context);
    PrepareJoints(world, island, warmScale);

    for (int i = 0; i < m_context.substeps; ++i)
    {
        SubStep(i == 0, step);
    }
    CloseStep();
    m_contacts.Restitution(m_context);
    m_contacts.Store(world.contacts, m_context);
    for (Joint* joint : m_joints)
    {
        ScaleJointImpulses(*joint, Real(m_context.substeps));
    }
    m_revolutes.Store(Real(m_context.substeps));

    ScatterSoftBodies(m_bodies, island, world.tasks);
    FinishBodies(world, island, world.tasks);
    world.solvedContacts.Record(m_contacts.SolvedContacts(), m_contacts.AnyHitEvents(), step);
    if (world.allowSleep)
    {
        UpdateSleep(world, island, step, true);
    }
}

void SoftStepSolver::SubStep(bool first, const StepContext& step)
{
    // Velocity Verlet: the step's first kick is half a sub-step (CloseStep gives the other
    // half at the end), and so are its constraint impulses: the warm start applies half of
    // last sub-step's, and what the kick accumulates is doubled back to a whole sub-step's.
    const Real kick = first ? Real(0.5) : Real(1);
    m_context.halfKick = first;
    IntegrateSoftVelocities(m_bodies, first, m_context.tasks);
    ScaleImpulses(kick);
    WarmStartJoints();
    m_contacts.WarmStart(m_context);
    SolveJoints(true);
    m_contacts.Solve(m_context, true);
    m_tree.Solve(m_context, true, true);
    IntegrateSoftPositions(m_bodies, m_context.h, step, m_context.tasks);
    m_contacts.BodiesMoved();
    if (m_context.contactModel == SoftContactModel::Rigid)
    {
        m_contacts.CorrectPositions(m_context);
    }
    CorrectJoints(step);
    for (int r = 0; r < step.solver.softStep.relaxIterations; ++r)
    {
        SolveJoints(false);
        m_contacts.Solve(m_context, false);
        m_tree.Solve(m_context, false, true);
    }
    if (m_contacts.RowByRow() && m_laneJoints.empty())
    {
        // A small island relaxes until its sweeps agree: an impulse a sweep could not take back
        // (a contact's warm start handed on by a joint) would otherwise stay as motion.
        // Joints that only a tree solves, exactly, and no contacts: one relax sweep settles them.
        const bool exact = m_contacts.Empty() && m_sweeping.empty();
        const int sweeps =
            exact ? std::max(step.solver.softStep.relaxIterations, 1) : kMaxSoftRelaxSweeps;
        for (int r = step.solver.softStep.relaxIterations; r < sweeps; ++r)
        {
            m_before = m_bodies.velocities;
            SolveJoints(false);
            m_contacts.Solve(m_context, false);
            m_tree.Solve(m_context, false, true);
            if (!Changed(m_before, m_bodies.velocities))
            {
                break;
            }
        }
    }
    ScaleImpulses(Real(1) / kick);
    m_context.halfKick = false;
}

void SoftStepSolver::CorrectJoints(const StepContext& step)
{
    if (m_joints.empty() && m_laneJoints.empty() && m_tree.Empty())
    {
        return;
    }
    // Pseudo-velocities: the rows' impulses move the bodies through them, once, and they are
    // then forgotten, so a joint's gap never becomes motion.
    m_pseudo.assign(m_bodies.velocities.size(), Velocity{});
    std::swap(m_pseudo, m_bodies.velocities);
    const Softness solving = m_context.joint;
    m_context.joint = m_context.jointCorrection;
    m_context.correcting = true;
    m_revolutes.Correct(m_context);
    for (const std::size_t k : m_sweeping)
    {
        CorrectSoftJoint(*m_joints[k], m_frames[k], m_context);
    }
    m_tree.Solve(m_context, true, false);
    IntegrateSoftPositions(m_bodies, m_context.h, step, m_context.tasks);
    m_contacts.BodiesMoved();
    std::swap(m_pseudo, m_bodies.velocities);
    m_context.joint = solving;
    m_context.correcting = false;
}

void SoftStepSolver::ScaleImpulses(Real factor)
{
    if (factor == 1)
    {
        return;
    }
    m_contacts.ScaleImpulses(factor);
    m_revolutes.ScaleImpulses(factor);
    for (Joint* joint : m_joints)
    {
        ScaleJointImpulses(*joint, factor);
    }
}

void SoftStepSolver::CloseStep()
{
    // Half a sub-step's kick, with half of the sub-step's constraint impulses, then one rigid
    // sweep; the accumulated impulses stay the last whole sub-step's (next step's warm start).
    IntegrateSoftVelocities(m_bodies, true, m_context.tasks);
    m_context.halfKick = true;
    m_context.closing = true;
    m_contacts.SaveImpulses();
    m_contacts.ScaleImpulses(Real(0.5));
    m_contacts.WarmStart(m_context);
    m_revolutes.CloseStep(m_context);
    for (std::size_t k = 0; k < m_joints.size(); ++k)
    {
        Joint scratch = *m_joints[k];
        ScaleJointImpulses(scratch, Real(0.5));
        WarmStartSoftJoint(scratch, m_frames[k], m_context);
        SolveSoftJoint(scratch, m_frames[k], m_context, false);
    }
    m_contacts.Solve(m_context, false);
    m_tree.Solve(m_context, false, false);
    m_contacts.RestoreImpulses();
    m_context.halfKick = false;
    m_context.closing = false;
}

void SoftStepSolver::PrepareJoints(SolverWorld& world, const Island& island, Real warmScale)
{
    const std::size_t count = island.joints.size();
    m_joints.resize(count);
    m_frames.resize(count);
    m_candidates.resize(count);
    // Each joint writes only itself, its frame and its slots here (a gear copies its other
    // bodies, which it only reads): any thread may take any range of them.
    ForEachIndex(m_context.tasks, static_cast<int>(count), kMinSoftJointsPerTask,
                 [&](int i)
                 {
                     const auto k = static_cast<std::size_t>(i);
                     Joint& joint = world.joints[island.joints[k]].joint;
                     const Body& bodyA = world.bodies[joint.bodyA];
                     const Body& bodyB = world.bodies[joint.bodyB];
                     StoreOtherJointBodies(joint, world.bodies);
                     PrepareSoftJoint(joint, m_frames[k], JointBodyOf(bodyA), JointBodyOf(bodyB),
                                      m_bodies.start[bodyA.islandIndex],
                                      m_bodies.start[bodyB.islandIndex], warmScale, m_context);
                     m_joints[k] = &joint;
                     m_candidates[k] = SoftRevoluteLanes::LaneJoint(joint, m_context);
                 });
    const std::size_t bodyCount = m_bodies.start.size();
    if (m_context.step->solver.softStep.jointTrees)
    {
        m_tree.Select(m_joints, m_frames, bodyCount, m_context.tasks);
    }
    // The lane candidates and their positions in island order, on the threads; a tree's
    // joints are solved with their tree, not in lanes.
    m_laneJoints.resize(count);
    m_laneRows.resize(count);
    const auto laneCandidates = static_cast<std::size_t>(StableCompact(
        m_context.tasks, static_cast<int>(count), m_pieceCounts,
        [&](int k)
        {
            const auto i = static_cast<std::size_t>(k);
            return m_candidates[i] != nullptr && !m_frames[i].pointInTree;
        },
        [&](int k, std::int32_t position)
        {
            m_laneJoints[static_cast<std::size_t>(position)] =
                m_candidates[static_cast<std::size_t>(k)];
            m_laneRows[static_cast<std::size_t>(position)] = k;
        }));
    m_laneJoints.resize(laneCandidates);
    m_laneRows.resize(laneCandidates);
    SplitLaneJoints(laneCandidates >= kMinSoftLaneRows);
    m_tree.Build(m_joints, m_frames, bodyCount);
    // A tree's plain revolute joints have nothing left to solve one by one.
    m_sweeping.clear();
    for (std::size_t k = 0; k < m_joints.size(); ++k)
    {
        if (SoftJointSweeps(*m_joints[k], m_frames[k]))
        {
            m_sweeping.push_back(k);
        }
    }
}

void SoftStepSolver::SplitLaneJoints(bool useLanes)
{
    if (!useLanes)
    {
        m_laneJoints.clear();
        m_laneRows.clear();
    }
    m_revolutes.Prepare(m_laneJoints, m_frames, m_laneRows, m_bodies.DiscardIndex(),
                        m_context.tasks);
    if (m_laneRows.empty())
    {
        return;
    }
    // The joints the lanes took leave the scalar list; the others, and the lane joints no
    // colour had room for, stay in island order.
    m_inLanes.assign(m_joints.size(), 0);
    for (const std::int32_t k : m_laneRows)
    {
        m_inLanes[static_cast<std::size_t>(k)] = 1;
    }
    for (const std::int32_t i : m_revolutes.Overflow())
    {
        m_inLanes[m_laneRows[i]] = 0;
    }
    std::size_t kept = 0;
    for (std::size_t k = 0; k < m_joints.size(); ++k)
    {
        if (m_inLanes[k] != 0)
        {
            continue;
        }
        if (kept != k)
        {
            m_joints[kept] = m_joints[k];
            m_frames[kept] = m_frames[k];
        }
        ++kept;
    }
    m_joints.resize(kept);
    m_frames.resize(kept);
}

void SoftStepSolver::WarmStartJoints()
{
    m_revolutes.WarmStart(m_context);
    for (std::size_t k = 0; k < m_joints.size(); ++k)
    {
        WarmStartSoftJoint(*m_joints[k], m_frames[k], m_context);
    }
}

void SoftStepSolver::SolveJoints(bool useBias)
{
    m_revolutes.Solve(m_context, useBias);
    for (const std::size_t k : m_sweeping)
    {
        SolveSoftJoint(*m_joints[k], m_frames[k], m_context, useBias);
    }
}

} // namespace meff::detail
