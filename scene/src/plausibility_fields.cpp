// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The scene file's "plausibility" section: every threshold a number ≥ 0, "rest" and "hold"
// objects.
#include "plausibility_fields.h"

namespace meff::scene_detail
{

namespace
{

/// A number ≥ 0 into `target` when present and valid; reported otherwise.
void ReadThreshold(ObjectReader& reader, std::string_view key, double& target)
{
    const std::optional<double> value = reader.Number(key, target);
    if (value && CheckNonNegative(reader, key, *value))
    {
        target = *value;
    }
}

} // namespace

void ReadPlausibility(ObjectReader& reader, ScenePlausibility& plausibility)
{
    ReadThreshold(reader, "energy_gain", plausibility.energyGain);
    ReadThreshold(reader, "energy_lift", plausibility.energyLift);
    ReadThreshold(reader, "energy_speed", plausibility.energySpeed);
    ReadThreshold(reader, "rebound_speed", plausibility.reboundSpeed);
    ReadThreshold(reader, "rebound_approach", plausibility.reboundApproach);
    ReadThreshold(reader, "penetration", plausibility.penetration);
    ReadThreshold(reader, "joint_gap", plausibility.jointGap);
    if (reader.Find("max_speed") != nullptr)
    {
        const std::optional<double> value = reader.Number("max_speed", std::nullopt);
        if (value && CheckNonNegative(reader, "max_speed", *value))
        {
            plausibility.maxSpeed = *value;
        }
    }
    if (reader.Find("max_rise") != nullptr)
    {
        const std::optional<double> value = reader.Number("max_rise", std::nullopt);
        if (value && CheckNonNegative(reader, "max_rise", *value))
        {
            plausibility.maxRise = *value;
        }
    }
    if (const Json* rest = reader.Object("rest", false))
    {
        ObjectReader restReader(reader.Diag(), *rest, reader.PathOf("rest"));
        ScenePlausibilityRest& check = plausibility.rest.emplace();
        const std::optional<double> after = restReader.Number("after", std::nullopt);
        if (after && CheckNonNegative(restReader, "after", *after))
        {
            check.after = *after;
        }
        ReadThreshold(restReader, "speed", check.speed);
        restReader.Finish();
    }
    if (const Json* hold = reader.Object("hold", false))
    {
        ObjectReader holdReader(reader.Diag(), *hold, reader.PathOf("hold"));
        ScenePlausibilityHold& check = plausibility.hold.emplace();
        ReadThreshold(holdReader, "after", check.after);
        const std::optional<double> distance = holdReader.Number("distance", std::nullopt);
        if (distance && CheckNonNegative(holdReader, "distance", *distance))
        {
            check.distance = *distance;
        }
        holdReader.Finish();
    }
    reader.Finish();
}

} // namespace meff::scene_detail
