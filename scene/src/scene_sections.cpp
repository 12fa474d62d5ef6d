// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "scene_sections.h"

#include <tuple>

namespace meff::scene_detail
{

SectionJson PairJson(SceneVec2 v)
{
    return SectionJson::array({v.x, v.y});
}

std::optional<SectionJson> SoftStepJson(const SoftStepSettings& soft)
{
    // The Real members go as the doubles they convert to, which the loader turns back into
    // the same floats.
    const SoftStepSettings defaults;
    SectionJson out = SectionJson::object();
    if (soft.substeps != defaults.substeps)
    {
        out["substeps"] = soft.substeps;
    }
    if (soft.relaxIterations != defaults.relaxIterations)
    {
        out["relax_iterations"] = soft.relaxIterations;
    }
    if (soft.contacts != defaults.contacts)
    {
        out["contacts"] = soft.contacts == SoftContactModel::Rigid ? "rigid" : "soft";
    }
    if (soft.jointTrees != defaults.jointTrees)
    {
        out["joint_trees"] = soft.jointTrees;
    }
    const std::tuple<const char*, Real, Real> numbers[] = {
        {"contact_correction", soft.contactCorrection, defaults.contactCorrection},
        {"contact_hertz", soft.contactHertz, defaults.contactHertz},
        {"contact_damping_ratio", soft.contactDampingRatio, defaults.contactDampingRatio},
        {"max_push_out_speed", soft.maxPushOutSpeed, defaults.maxPushOutSpeed},
        {"joint_hertz", soft.jointHertz, defaults.jointHertz},
        {"joint_damping_ratio", soft.jointDampingRatio, defaults.jointDampingRatio}};
    for (const auto& [name, value, fallback] : numbers)
    {
        if (value != fallback)
        {
            out[name] = double(value);
        }
    }
    if (out.empty())
    {
        return std::nullopt;
    }
    return out;
}

std::optional<SectionJson> PlausibilityJson(const ScenePlausibility& p)
{
    const ScenePlausibility defaults;
    if (p == defaults)
    {
        return std::nullopt;
    }
    SectionJson out = SectionJson::object();
    const std::tuple<const char*, double, double> thresholds[] = {
        {"energy_gain", p.energyGain, defaults.energyGain},
        {"energy_lift", p.energyLift, defaults.energyLift},
        {"energy_speed", p.energySpeed, defaults.energySpeed},
        {"rebound_speed", p.reboundSpeed, defaults.reboundSpeed},
        {"rebound_approach", p.reboundApproach, defaults.reboundApproach},
        {"penetration", p.penetration, defaults.penetration},
        {"joint_gap", p.jointGap, defaults.jointGap}};
    for (const auto& [name, value, fallback] : thresholds)
    {
        if (value != fallback)
        {
            out[name] = value;
        }
    }
    if (p.maxSpeed)
    {
        out["max_speed"] = *p.maxSpeed;
    }
    if (p.maxRise)
    {
        out["max_rise"] = *p.maxRise;
    }
    if (p.rest)
    {
        out["rest"] = {{"after", p.rest->after}, {"speed", p.rest->speed}};
    }
    if (p.hold)
    {
        out["hold"] = {{"after", p.hold->after}, {"distance", p.hold->distance}};
    }
    return out;
}

std::optional<SectionJson> ValidateJson(const SceneTolerances& t, const SceneValidation& v)
{
    const SceneTolerances defaults;
    SectionJson validate = SectionJson::object();
    if (t != defaults)
    {
        validate["tolerances"] = {{"position", t.position},
                                  {"angle", t.angle},
                                  {"velocity", t.velocity},
                                  {"impulse", t.impulse},
                                  {"impulse_relative", t.impulseRelative}};
    }
    if (v.chaotic)
    {
        validate["chaotic"] = true;
        validate["horizon_frames"] = v.horizonFrames;
    }
    if (v.settle)
    {
        SectionJson settle = {{"position", v.settle->position}};
        if (v.settle->angle)
        {
            settle["angle"] = *v.settle->angle;
        }
        if (v.settle->minimumHeight)
        {
            settle["min_height"] = *v.settle->minimumHeight;
        }
        validate["settle"] = settle;
    }
    if (validate.empty())
    {
        return std::nullopt;
    }
    return validate;
}

SectionJson RenderJson(const SceneCamera& camera)
{
    return {{"camera", {{"center", PairJson(camera.center)}, {"height", camera.height}}}};
}

SectionJson AnalyticJson(const Scene& scene)
{
    const SceneAnalytic& analytic = *scene.analytic;
    static const char* const kKinds[] = {"pendulum", "cradle", "bounce"};
    SectionJson out = {{"kind", kKinds[int(analytic.kind)]}};
    switch (analytic.kind)
    {
    case SceneAnalyticKind::Pendulum:
        out["joint"] = scene.joints.at(analytic.joints.at(0)).name;
        break;
    case SceneAnalyticKind::Cradle:
        out["joints"] = SectionJson::array();
        for (const std::size_t joint : analytic.joints)
        {
            out["joints"].push_back(scene.joints.at(joint).name);
        }
        break;
    case SceneAnalyticKind::Bounce:
        out["body"] = scene.bodies.at(analytic.body).name;
        out["contact_height"] = analytic.contactHeight;
        break;
    }
    return out;
}

} // namespace meff::scene_detail
