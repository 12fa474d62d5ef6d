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

/// A required number ≥ 0: its value when present and valid; reported and empty otherwise.
std::optional<double> RequiredThreshold(ObjectReader& reader, std::string_view key)
{
    const std::optional<double> value = reader.Number(key, std::nullopt);
    return value && CheckNonNegative(reader, key, *value) ? value : std::nullopt;
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
        plausibility.maxSpeed = RequiredThreshold(reader, "max_speed");
    }
    if (reader.Find("max_rise") != nullptr)
    {
        plausibility.maxRise = RequiredThreshold(reader, "max_rise");
    }
    if (const Json* rest = reader.Object("rest", false))
    {
        ObjectReader restReader(reader.Diag(), *rest, reader.PathOf("rest"));
        ScenePlausibilityRest& check = plausibility.rest.emplace();
        if (const std::optional<double> after = RequiredThreshold(restReader, "after"))
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
        if (const std::optional<double> distance = RequiredThreshold(holdReader, "distance"))
        {
            check.distance = *distance;
        }
        holdReader.Finish();
    }
    reader.Finish();
}

} // namespace meff::scene_detail
