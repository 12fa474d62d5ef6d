// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// meff's state after a step, in the comparison's terms (meff_sampler.h).
#include "meff_sampler.h"

#include <span>

namespace meff::validation
{

MeffSampler::MeffSampler(const BuiltScene& built) : m_built(built)
{
    for (std::size_t i = 0; i < built.shapes.size(); ++i)
    {
        for (std::size_t k = 0; k < built.shapes[i].size(); ++k)
        {
            m_shapeOf.emplace(built.shapes[i][k].index, ShapeKey{i, k, 0});
            // A chain's segments are its children, in order (Box2D's child index).
            if (!built.chains[i][k].IsNull())
            {
                const std::span<const ShapeId> segments =
                    built.world.GetChainSegments(built.chains[i][k]);
                for (std::size_t child = 1; child < segments.size(); ++child)
                {
                    m_shapeOf.emplace(segments[child].index, ShapeKey{i, k, child});
                }
            }
        }
    }
}

FrameSample MeffSampler::Sample(Real invDt) const
{
    const World& world = m_built.world;
    FrameSample sample;
    sample.bodies.reserve(m_built.bodies.size());
    for (const BodyId id : m_built.bodies)
    {
        const Vec2 p = world.GetPosition(id);
        const Vec2 v = world.GetLinearVelocity(id);
        sample.bodies.push_back({p.x, p.y, world.GetAngle(id), v.x, v.y,
                                 world.GetAngularVelocity(id), world.IsAwake(id)});
    }
    for (const ContactPointReport& report : world.GetContactReports())
    {
        const ShapeKey& a = m_shapeOf.at(report.shapeA.index);
        const ShapeKey& b = m_shapeOf.at(report.shapeB.index);
        ContactSample contact;
        contact.key = {a.body, a.shape, b.body, b.shape, report.featureKey, a.child, b.child};
        contact.normalImpulse = report.normalImpulse;
        contact.tangentImpulse = report.tangentImpulse;
        sample.contacts.push_back(contact);
    }
    sample.joints.reserve(m_built.joints.size());
    for (const JointId id : m_built.joints)
    {
        const JointReaction reaction = world.GetReaction(id, invDt);
        sample.joints.push_back({reaction.force.x, reaction.force.y, reaction.torque});
    }
    return sample;
}

} // namespace meff::validation
