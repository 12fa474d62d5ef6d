// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A run's frames added up into its ValidationResult (run_tally.h).
#include "run_tally.h"

#include <cmath>

namespace meff::validation
{

namespace
{

void Track(RunMaximum& maximum, double value, int frame, const std::string& where)
{
    if (value > maximum.value || (std::isnan(value) && !std::isnan(maximum.value)))
    {
        maximum.value = value;
        maximum.frame = frame;
        maximum.where = where;
    }
}

} // namespace

void TallyFrame(ValidationResult& result, const Scene& scene, int frame, const FrameSample& meff,
                const FrameSample& reference, double dt)
{
    FrameErrors errors = CompareFrames(meff, reference, dt, result.tolerances, frame);
    Track(result.position, errors.position, frame, DescribeBody(scene, errors.positionBody));
    Track(result.angle, errors.angle, frame, DescribeBody(scene, errors.angleBody));
    Track(result.velocity, errors.velocity, frame, DescribeBody(scene, errors.velocityBody));
    Track(result.contactImpulse, errors.contactImpulse, frame,
          errors.contact ? DescribeContact(scene, *errors.contact) : "-");
    Track(result.jointImpulse, errors.jointImpulse, frame, DescribeJoint(scene, errors.joint));
    result.onlyInMeff += errors.onlyInMeff;
    result.onlyInBox2D += errors.onlyInBox2D;
    result.awakeMismatches += errors.awakeMismatches;
    if (errors.Exceeds() && !result.divergenceFrame)
    {
        result.divergenceFrame = frame;
        result.divergenceQuantities = errors.exceeded;
        result.divergenceDetails =
            DescribeDivergence(scene, errors, meff, reference, dt, result.tolerances);
    }
    result.perFrame.push_back(std::move(errors));
}

} // namespace meff::validation
