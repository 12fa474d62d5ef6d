// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Baselines: a scene's run in one of meff's own back ends, recorded once (every frame's
// FrameSample: each body's position, angle, velocities and awake flag, each contact point's
// impulses, each joint's reaction), and later runs compared with it frame by frame by the same
// comparison as Box2D's (meff/validation.h). What a team that ships the colour or soft-step
// back end, which Box2D 2.4.1 cannot mirror, compares a new build with: its last good run.
//
// The file is gzip-compressed (zlib); inside, a first line "meff-baseline 1", a JSON header
// line (BaselineHeader) and the frames in little-endian binary, doubles bit for bit.
#pragma once

#include "meff/error.h"
#include "meff/scene.h"
#include "meff/validation.h"

#include <string>
#include <string_view>
#include <vector>

namespace meff::validation
{

/// The file format's version: a baseline of another version is refused (re-record it).
inline constexpr int kBaselineFormatVersion = 1;

/// What a baseline was recorded from: a run compared with it must match (CheckBaseline).
struct BaselineHeader
{
    std::string meffVersion; ///< the meff that recorded it (said, not checked)
    std::string backEnd;     ///< "box2d", "colour" or "soft_step"
    std::string scene;       ///< the scene's name
    std::string sceneHash;   ///< "fnv1a64:" and 16 hex digits of the scene file's bytes
    /// The "world" section the run used (scene file, --solver, --block-solver, --frames
    /// applied), as a scene file writes it: JSON text.
    std::string settings;
    int frames = 0; ///< steps recorded (frames + 1 samples: frame 0 is the world as built)
    int bodies = 0;
    int joints = 0;
};

/// A recorded run: frames[k] is the state after step k (frames[0]: as built).
struct Baseline
{
    BaselineHeader header;
    std::vector<FrameSample> frames;
};

/// A baseline that cannot be recorded, read or used: what() is one line naming the file and
/// what is wrong or differs.
class BaselineError : public Error
{
  public:
    using Error::Error;
};

/// The header a run of `scene` would record: the scene as given (its world.solver the back end
/// that runs), `options.frames` and `options.blockSolver` applied. Reads the scene's file
/// (scene.sourcePath) for its hash; throws BaselineError when it cannot.
BaselineHeader HeaderFor(const Scene& scene, const RunOptions& options,
                         const std::string& meffVersion);

/// Runs the scene in its own back end and records every frame. Throws BaselineError when the
/// run stops (a non-finite state), SceneError when the scene cannot be built.
Baseline RecordBaseline(const Scene& scene, const RunOptions& options,
                        const std::string& meffVersion);

/// The baseline as its file's bytes (gzip).
std::string EncodeBaseline(const Baseline& baseline);

/// The baseline in `bytes`, read from `path` (named in errors). Throws BaselineError when the
/// bytes are not a baseline, are corrupt or truncated, or are another format version.
Baseline DecodeBaseline(std::string_view bytes, const std::string& path);

/// Throws BaselineError (naming `path`, the recorded and the current value) when `recorded`
/// does not fit the run `current` describes: another back end, frame count, body or joint
/// count always; another scene file or settings unless `acceptSceneChange`.
void CheckBaseline(const BaselineHeader& recorded, const BaselineHeader& current,
                   const std::string& path, bool acceptSceneChange);

/// Runs the scene as RecordBaseline does and compares every frame with the baseline's, within
/// `tolerances` (all 0: bit for bit). The result is read as Validate's is, its reference
/// "baseline"; options.meffVelocityIterations changes the run on purpose, as in Validate.
ValidationResult CompareWithBaseline(const Scene& scene, const Baseline& baseline,
                                     const RunOptions& options, const Tolerances& tolerances);

} // namespace meff::validation
