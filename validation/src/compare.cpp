// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The comparison of one frame between meff and Box2D (see meff/validation.h for the rules).
#include "meff/validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <tuple>

namespace meff::validation
{

namespace
{

/// A shape (or a chain's segment): body, shape and child index.
using ShapeKey = std::tuple<std::size_t, std::size_t, std::size_t>;
/// The unordered shape pair plus the feature key: equal for the same point in both engines.
using MatchKey = std::tuple<ShapeKey, ShapeKey, std::uint32_t>;

MatchKey MatchKeyOf(const ContactKey& key)
{
    ShapeKey a{key.bodyA, key.shapeA, key.childA};
    ShapeKey b{key.bodyB, key.shapeB, key.childB};
    if (b < a)
    {
        std::swap(a, b);
    }
    return {a, b, key.featureKey};
}

double Allowance(const Tolerances& tolerances, double reference)
{
    return std::max(tolerances.impulse, tolerances.impulseRelative * std::abs(reference));
}

/// Error and error/allowance of one impulse against Box2D's value.
std::pair<double, double> ImpulseError(double meff, double box2d, const Tolerances& tolerances)
{
    const double error = std::abs(meff - box2d);
    const double allowance = Allowance(tolerances, box2d);
    return {error, allowance > 0 ? error / allowance : (error > 0 ? HUGE_VAL : 0.0)};
}

void NoteContact(FrameErrors& errors, const ContactKey& key, double error, double ratio)
{
    if (error > errors.contactImpulse || std::isnan(error))
    {
        errors.contactImpulse = error;
        errors.contact = key;
    }
    errors.contactRatio = std::max(errors.contactRatio, std::isnan(ratio) ? HUGE_VAL : ratio);
}

void CompareBodies(const FrameSample& meff, const FrameSample& box2d, FrameErrors& errors)
{
    for (std::size_t i = 0; i < meff.bodies.size(); ++i)
    {
        const BodySample& m = meff.bodies[i];
        const BodySample& b = box2d.bodies[i];
        const int body = static_cast<int>(i);
        const double position = std::hypot(m.x - b.x, m.y - b.y);
        const double angle = std::abs(m.angle - b.angle);
        const double linear = std::hypot(m.vx - b.vx, m.vy - b.vy);
        const double angular = std::abs(m.angularVelocity - b.angularVelocity);
        // NaN compares false: a non-finite state must still count as the largest error.
        const auto larger = [](double value, double current)
        { return value > current || (std::isnan(value) && !std::isnan(current)); };
        if (larger(position, errors.position))
        {
            errors.position = position;
            errors.positionBody = body;
        }
        if (larger(angle, errors.angle))
        {
            errors.angle = angle;
            errors.angleBody = body;
        }
        errors.awakeMismatches += m.awake != b.awake ? 1 : 0;
        errors.linearVelocity = std::max(errors.linearVelocity, linear);
        errors.angularVelocity = std::max(errors.angularVelocity, angular);
        const double velocity = std::max(linear, angular);
        if (larger(velocity, errors.velocity) || std::isnan(linear) || std::isnan(angular))
        {
            errors.velocity = std::isnan(linear) || std::isnan(angular) ? NAN : velocity;
            errors.velocityBody = body;
        }
    }
}

void CompareContacts(const FrameSample& meff, const FrameSample& box2d,
                     const Tolerances& tolerances, FrameErrors& errors)
{
    errors.contactPointsMeff = static_cast<int>(meff.contacts.size());
    errors.contactPointsBox2D = static_cast<int>(box2d.contacts.size());

    std::multimap<MatchKey, std::size_t> box2dPoints;
    for (std::size_t i = 0; i < box2d.contacts.size(); ++i)
    {
        box2dPoints.emplace(MatchKeyOf(box2d.contacts[i].key), i);
    }
    for (const ContactSample& m : meff.contacts)
    {
        // The first unmatched Box2D point with this key: a contact reported again in a
        // time-of-impact sub-step pairs with the engines' reports in order.
        const MatchKey key = MatchKeyOf(m.key);
        const auto found = box2dPoints.lower_bound(key);
        double normalB = 0;
        double tangentB = 0;
        if (found == box2dPoints.end() || found->first != key)
        {
            ++errors.onlyInMeff;
        }
        else
        {
            const ContactSample& b = box2d.contacts[found->second];
            normalB = b.normalImpulse;
            tangentB = b.tangentImpulse;
            box2dPoints.erase(found);
        }
        const auto [normalError, normalRatio] = ImpulseError(m.normalImpulse, normalB, tolerances);
        const auto [tangentError, tangentRatio] =
            ImpulseError(m.tangentImpulse, tangentB, tolerances);
        NoteContact(errors, m.key, std::max(normalError, tangentError),
                    std::max(normalRatio, tangentRatio));
    }
    // What is left exists only in Box2D: meff's impulse there is zero.
    for (const auto& [key, index] : box2dPoints)
    {
        const ContactSample& b = box2d.contacts[index];
        ++errors.onlyInBox2D;
        const auto [normalError, normalRatio] = ImpulseError(0, b.normalImpulse, tolerances);
        const auto [tangentError, tangentRatio] = ImpulseError(0, b.tangentImpulse, tolerances);
        NoteContact(errors, b.key, std::max(normalError, tangentError),
                    std::max(normalRatio, tangentRatio));
    }
}

void CompareJoints(const FrameSample& meff, const FrameSample& box2d, double dt,
                   const Tolerances& tolerances, FrameErrors& errors)
{
    for (std::size_t j = 0; j < meff.joints.size(); ++j)
    {
        const JointSample& m = meff.joints[j];
        const JointSample& b = box2d.joints[j];
        const double forceError = std::hypot(m.fx - b.fx, m.fy - b.fy) * dt;
        const double forceAllowance = Allowance(tolerances, std::hypot(b.fx, b.fy) * dt);
        const double torqueError = std::abs(m.torque - b.torque) * dt;
        const double torqueAllowance = Allowance(tolerances, b.torque * dt);
        const double error = std::max(forceError, torqueError);
        const double ratio = std::max(forceAllowance > 0 ? forceError / forceAllowance : 0.0,
                                      torqueAllowance > 0 ? torqueError / torqueAllowance : 0.0);
        if (error > errors.jointImpulse || std::isnan(error))
        {
            errors.jointImpulse = error;
            errors.joint = static_cast<int>(j);
        }
        errors.jointRatio = std::max(errors.jointRatio, std::isnan(ratio) ? HUGE_VAL : ratio);
    }
}

/// True when value is within tolerance; NaN never is.
bool Within(double value, double tolerance)
{
    return value <= tolerance;
}

} // namespace

Tolerances TolerancesOf(const SceneTolerances& scene)
{
    Tolerances tolerances;
    tolerances.position = scene.position;
    tolerances.angle = scene.angle;
    tolerances.velocity = scene.velocity;
    tolerances.impulse = scene.impulse;
    tolerances.impulseRelative = scene.impulseRelative;
    return tolerances;
}

FrameErrors CompareFrames(const FrameSample& meff, const FrameSample& box2d, double dt,
                          const Tolerances& tolerances, int frame)
{
    if (meff.bodies.size() != box2d.bodies.size() || meff.joints.size() != box2d.joints.size())
    {
        throw std::invalid_argument("CompareFrames: the two frames describe different scenes (" +
                                    std::to_string(meff.bodies.size()) + " vs " +
                                    std::to_string(box2d.bodies.size()) + " bodies, " +
                                    std::to_string(meff.joints.size()) + " vs " +
                                    std::to_string(box2d.joints.size()) + " joints)");
    }
    FrameErrors errors;
    errors.frame = frame;
    CompareBodies(meff, box2d, errors);
    CompareContacts(meff, box2d, tolerances, errors);
    CompareJoints(meff, box2d, dt, tolerances, errors);

    if (errors.awakeMismatches > 0)
    {
        errors.exceeded.emplace_back("awake");
    }
    if (!Within(errors.position, tolerances.position))
    {
        errors.exceeded.emplace_back("position");
    }
    if (!Within(errors.angle, tolerances.angle))
    {
        errors.exceeded.emplace_back("angle");
    }
    if (!Within(errors.velocity, tolerances.velocity))
    {
        errors.exceeded.emplace_back("velocity");
    }
    if (!Within(errors.contactRatio, 1.0))
    {
        errors.exceeded.emplace_back("contact_impulse");
    }
    if (!Within(errors.jointRatio, 1.0))
    {
        errors.exceeded.emplace_back("joint_impulse");
    }
    return errors;
}

bool SameContactPoint(const ContactKey& a, const ContactKey& b)
{
    return MatchKeyOf(a) == MatchKeyOf(b);
}

std::string DescribeBody(const Scene& scene, int body)
{
    if (body < 0 || static_cast<std::size_t>(body) >= scene.bodies.size())
    {
        return "-";
    }
    const std::string& name = scene.bodies[static_cast<std::size_t>(body)].name;
    return name.empty() ? "bodies[" + std::to_string(body) + "]" : name;
}

std::string DescribeContact(const Scene& scene, const ContactKey& key)
{
    char featureKey[16];
    std::snprintf(featureKey, sizeof featureKey, "0x%x", static_cast<unsigned>(key.featureKey));
    // A chain's segment is named by its shape and child index: ground[0.3].
    const auto shape = [&](std::size_t body, std::size_t index, std::size_t child)
    {
        const bool chain = body < scene.bodies.size() && index < scene.bodies[body].shapes.size() &&
                           scene.bodies[body].shapes[index].type == SceneShapeType::Chain;
        return DescribeBody(scene, static_cast<int>(body)) + "[" + std::to_string(index) +
               (chain ? "." + std::to_string(child) : std::string()) + "]";
    };
    return shape(key.bodyA, key.shapeA, key.childA) + "/" +
           shape(key.bodyB, key.shapeB, key.childB) + " key " + featureKey;
}

std::string DescribeJoint(const Scene& scene, int joint)
{
    if (joint < 0 || static_cast<std::size_t>(joint) >= scene.joints.size())
    {
        return "-";
    }
    const std::string& name = scene.joints[static_cast<std::size_t>(joint)].name;
    return name.empty() ? "joints[" + std::to_string(joint) + "]" : name;
}

} // namespace meff::validation
