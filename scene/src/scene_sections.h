// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The sections of a meff scene file that say how a scene is judged and shown rather than what
// it holds (world.soft_step, validate, plausibility, render, analytic), as JSON in the scene
// format's field names: written by the scene writer (WriteScene) into the file, and by the
// b2dJson export into its "meff.*" custom properties.
#pragma once

#include "b2djson_values.h"

#include "meff/scene.h"

#include <optional>

namespace meff::scene_detail
{

using SectionJson = b2djson_detail::OrderedJson;

/// [x, y].
SectionJson PairJson(SceneVec2 v);
/// world.soft_step with the members that differ from the defaults; nothing when none does.
std::optional<SectionJson> SoftStepJson(const SoftStepSettings& soft);
/// "validate" when anything in it differs from the defaults.
std::optional<SectionJson> ValidateJson(const SceneTolerances& tolerances,
                                        const SceneValidation& validation);
/// "plausibility", each field that differs from its default; nothing when none does.
std::optional<SectionJson> PlausibilityJson(const ScenePlausibility& plausibility);
/// "render" ({"camera": ...}).
SectionJson RenderJson(const SceneCamera& camera);
/// "analytic", naming the scene's joints and bodies.
SectionJson AnalyticJson(const Scene& scene);

} // namespace meff::scene_detail
