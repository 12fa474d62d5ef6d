// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Plausibility checks: what any back end must do on any scene, whatever its constraint order.
// A regression team cannot compare the soft step or the colour back end with Box2D frame by
// frame (they are other solvers), but it can check physics: no NaN, no energy from nowhere, no
// rebound where restitution is 0, joints that hold, no tunnelling, no speed spikes, stacks
// that come to rest, structures that stand. The thresholds are the scene's ("plausibility" in the
// scene file, meff::ScenePlausibility); docs/validation.md says what each check measures.
#pragma once

#include "meff/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace meff::validation
{

/// One invariant over one run.
struct PlausibilityCheck
{
    std::string name;      ///< "finite", "energy", "rebound", "joint_gap", "penetration", ...
    bool applies = true;   ///< false: not checked on this scene (`note` says why)
    bool passed = true;    ///< value ≤ limit (always true when it does not apply)
    double value = 0;      ///< the figure measured (unit per check, see `unit`)
    double limit = 0;      ///< the threshold it was held to
    const char* unit = ""; ///< "J", "m/s", "m", "" (finite: the count of bad values)
    int frame = -1;        ///< the frame where `value` was measured; -1: none
    std::string where;     ///< the body, joint or contact it belongs to
    std::string note;      ///< how the limit was made up, or why the check does not apply
};

struct PlausibilityResult
{
    std::string scene;
    std::string solver; ///< "box2d", "colour", "soft_step"
    int frames = 0;
    bool passed = true;
    std::vector<PlausibilityCheck> checks; ///< finite, energy, rebound, joint_gap, penetration,
                                           ///< max_speed, rise, rest, hold: always in this order
};

/// Runs `scene` for `frames` steps (default: its own) with `solver` as its back end (default:
/// its own; the other solver settings are the scene's) and checks every invariant.
/// Throws SceneError if the scene cannot be built.
PlausibilityResult CheckPlausibility(const Scene& scene, std::optional<SolverKind> solver = {},
                                     std::optional<int> frames = {});

/// "energy 3.1 J > 0.25 J at frame 61 (box2)": one line per failed check, "" when it passed.
std::string DescribeCheck(const PlausibilityCheck& check);

} // namespace meff::validation
