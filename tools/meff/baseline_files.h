// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff validate --baseline DIR`: where each scene's baseline file lives in DIR, recording it
// (whole or not at all) and comparing a run with it (meff/baseline.h), and the tolerances a
// comparison is held to.
#pragma once

#include "meff/baseline.h"

#include <optional>
#include <string>
#include <vector>

namespace meff::cli
{

/// DIR/<the scene's path relative to the working directory>.baseline.gz; a scene outside the
/// working directory goes by its absolute path below the root (DIR/tmp/x.json.baseline.gz).
std::string BaselineFile(const std::string& directory, const std::string& scenePath);

/// The limits a run is held to against its baseline: the Box2D comparison's defaults
/// (validation::Tolerances) changed by each "NAME=VALUE" of --tolerance (position, angle,
/// velocity, impulse, impulse_relative), or all 0 with `bitExact`.
validation::Tolerances BaselineTolerances(const std::vector<std::string>& settings, bool bitExact);

/// Empty when `setting` is a valid --tolerance NAME=VALUE, else why not (one line).
std::string CheckToleranceSetting(const std::string& setting);

/// Records the scene's run (its world.solver the back end to record) into `file`, creating its
/// folder; returns the line validate prints. Throws validation::BaselineError or
/// std::runtime_error (the file cannot be written) with one line.
std::string RecordBaselineFile(const Scene& scene, const validation::RunOptions& options,
                               const std::string& file);

/// Reads `file`, refuses it when it does not fit this run (validation::CheckBaseline), and
/// compares the run with it. Throws validation::BaselineError with one line naming the file
/// when it is missing, unreadable, corrupt, truncated or does not fit.
validation::ValidationResult CompareWithBaselineFile(const Scene& scene,
                                                     const validation::RunOptions& options,
                                                     const std::string& file,
                                                     const validation::Tolerances& tolerances,
                                                     bool acceptSceneChange);

} // namespace meff::cli
