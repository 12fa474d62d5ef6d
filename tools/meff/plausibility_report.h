// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff validate`'s plausibility checks (meff/plausibility.h) as the tool reports them: a line
// per scene, its summary.json section and its JUnit test case.
#pragma once

#include "junit.h"

#include "meff/plausibility.h"

#include <nlohmann/json.hpp>

#include <string>

namespace meff::cli
{

/// "PASS|FAIL plausibility SCENE (solver S, N frames): energy ..., rebound ..." and one
/// indented line per failed check, each ending in a newline.
std::string PlausibilityText(const validation::PlausibilityResult& result);

/// {"solver", "frames", "passed", "checks": {NAME: {applies, passed, value, limit, unit, frame,
/// where, note}}}.
nlohmann::json PlausibilityJson(const validation::PlausibilityResult& result);

/// Folds the checks into a scene's test case: a failed check makes it a failure of type
/// "plausibility" (unless it already failed), its message and lines added.
void AddPlausibilityToCase(const validation::PlausibilityResult& result, JUnitCase& testCase);

} // namespace meff::cli
