// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// What a divergence looks like: for each quantity that exceeded its tolerance at the divergence
// frame, where it happened and both engines' values, so a CI report says what went wrong
// without opening divergence.csv.
#include "meff/validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace meff::validation
{

namespace
{

/// Enough digits to tell two floats apart (9 significant digits).
std::string Number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

std::string Pair(double x, double y, const char* unit)
{
    return "(" + Number(x) + ", " + Number(y) + ") " + unit;
}

double Allowance(const Tolerances& tolerances, double reference)
{
    return std::max(tolerances.impulse, tolerances.impulseRelative * std::abs(reference));
}

DivergenceDetail BodyDetail(const Scene& scene, const std::string& quantity, int body,
                            const FrameSample& meff, const FrameSample& box2d, double error,
                            double tolerance)
{
    DivergenceDetail detail{quantity, DescribeBody(scene, body), "-", "-", error, tolerance};
    if (body < 0)
    {
        return detail;
    }
    const BodySample& m = meff.bodies[std::size_t(body)];
    const BodySample& b = box2d.bodies[std::size_t(body)];
    if (quantity == "position")
    {
        detail.meff = Pair(m.x, m.y, "m");
        detail.box2d = Pair(b.x, b.y, "m");
    }
    else if (quantity == "angle")
    {
        detail.meff = Number(m.angle) + " rad";
        detail.box2d = Number(b.angle) + " rad";
    }
    else
    {
        detail.meff = Pair(m.vx, m.vy, "m/s") + ", " + Number(m.angularVelocity) + " rad/s";
        detail.box2d = Pair(b.vx, b.vy, "m/s") + ", " + Number(b.angularVelocity) + " rad/s";
    }
    return detail;
}

/// The first point of `sample` that is `key`'s point, or nullptr.
const ContactSample* FindPoint(const FrameSample& sample, const ContactKey& key)
{
    for (const ContactSample& contact : sample.contacts)
    {
        if (SameContactPoint(contact.key, key))
        {
            return &contact;
        }
    }
    return nullptr;
}

std::string Impulses(const ContactSample* point)
{
    if (point == nullptr)
    {
        return "no such point";
    }
    return "normal " + Number(point->normalImpulse) + " N·s, tangent " +
           Number(point->tangentImpulse) + " N·s";
}

DivergenceDetail ContactDetail(const Scene& scene, const FrameErrors& errors,
                               const FrameSample& meff, const FrameSample& box2d,
                               const Tolerances& tolerances)
{
    DivergenceDetail detail{"contact_impulse", "-", "-", "-", errors.contactImpulse,
                            tolerances.impulse};
    if (!errors.contact)
    {
        return detail;
    }
    detail.where = DescribeContact(scene, *errors.contact);
    const ContactSample* m = FindPoint(meff, *errors.contact);
    const ContactSample* b = FindPoint(box2d, *errors.contact);
    detail.meff = Impulses(m);
    detail.box2d = Impulses(b);
    if (b != nullptr)
    {
        // The allowance of whichever impulse, normal or tangent, differs more.
        const double normalError = std::abs((m ? m->normalImpulse : 0) - b->normalImpulse);
        const double tangentError = std::abs((m ? m->tangentImpulse : 0) - b->tangentImpulse);
        detail.tolerance = Allowance(tolerances, normalError >= tangentError ? b->normalImpulse
                                                                             : b->tangentImpulse);
    }
    return detail;
}

DivergenceDetail JointDetail(const Scene& scene, const FrameErrors& errors, const FrameSample& meff,
                             const FrameSample& box2d, double dt, const Tolerances& tolerances)
{
    DivergenceDetail detail{
        "joint_impulse",   DescribeJoint(scene, errors.joint), "-", "-", errors.jointImpulse,
        tolerances.impulse};
    if (errors.joint < 0)
    {
        return detail;
    }
    const auto text = [dt](const JointSample& joint)
    {
        return "force·dt " + Pair(joint.fx * dt, joint.fy * dt, "N·s") + ", torque·dt " +
               Number(joint.torque * dt) + " N·m·s";
    };
    const JointSample& m = meff.joints[std::size_t(errors.joint)];
    const JointSample& b = box2d.joints[std::size_t(errors.joint)];
    detail.meff = text(m);
    detail.box2d = text(b);
    detail.tolerance = std::max(Allowance(tolerances, std::hypot(b.fx, b.fy) * dt),
                                Allowance(tolerances, b.torque * dt));
    return detail;
}

DivergenceDetail AwakeDetail(const Scene& scene, const FrameSample& meff, const FrameSample& box2d)
{
    DivergenceDetail detail{"awake", "-", "-", "-", 1, 0};
    for (std::size_t i = 0; i < meff.bodies.size(); ++i)
    {
        if (meff.bodies[i].awake != box2d.bodies[i].awake)
        {
            detail.where = DescribeBody(scene, int(i));
            detail.meff = meff.bodies[i].awake ? "awake" : "asleep";
            detail.box2d = box2d.bodies[i].awake ? "awake" : "asleep";
            break;
        }
    }
    return detail;
}

} // namespace

std::vector<DivergenceDetail> DescribeDivergence(const Scene& scene, const FrameErrors& errors,
                                                 const FrameSample& meff, const FrameSample& box2d,
                                                 double dt, const Tolerances& tolerances)
{
    std::vector<DivergenceDetail> details;
    for (const std::string& quantity : errors.exceeded)
    {
        if (quantity == "position")
        {
            details.push_back(BodyDetail(scene, quantity, errors.positionBody, meff, box2d,
                                         errors.position, tolerances.position));
        }
        else if (quantity == "angle")
        {
            details.push_back(BodyDetail(scene, quantity, errors.angleBody, meff, box2d,
                                         errors.angle, tolerances.angle));
        }
        else if (quantity == "velocity")
        {
            details.push_back(BodyDetail(scene, quantity, errors.velocityBody, meff, box2d,
                                         errors.velocity, tolerances.velocity));
        }
        else if (quantity == "contact_impulse")
        {
            details.push_back(ContactDetail(scene, errors, meff, box2d, tolerances));
        }
        else if (quantity == "joint_impulse")
        {
            details.push_back(JointDetail(scene, errors, meff, box2d, dt, tolerances));
        }
        else if (quantity == "awake")
        {
            details.push_back(AwakeDetail(scene, meff, box2d));
        }
    }
    return details;
}

} // namespace meff::validation
