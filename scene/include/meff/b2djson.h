// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// b2dJson: the JSON format of R.U.B.E. (the editor Box2D users make levels in) and of
// iforce2d's b2dJson loader. A level converts to a meff scene and back; docs/b2djson.md says
// field by field how, and what does not carry over.
//
// Import: every body, fixture and joint becomes the meff scene's, in the same order (so a
// level's body and joint indices are the scene's); the result is checked by the scene loader,
// and every problem is reported with the level's file and JSON path ("level.json:
// body[3].fixture[0].circle.radius: must be > 0, got -1"). What meff does not model (custom
// properties, images, inactive bodies, sub-stepping, hand-set mass) is left out with one
// warning line each.
//
// Export: the scene's bodies, shapes and joints in b2dJson's fields; what b2dJson has no field
// for (the scene's name, description, frames, meff's solver switches, validation and render
// settings, and meff's authoring forms: boxes, world-point anchors) travels in custom
// properties named "meff.*", which the editor keeps and the importer reads back, so that
// meff → b2dJson → meff gives the same scene.
#pragma once

#include "meff/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace meff
{

/// A scene read from a file of either format, with what was left out on the way.
struct LoadedScene
{
    Scene scene;
    /// One line each, "FILE: warning: ...": what a b2dJson level holds that the scene does not.
    std::vector<std::string> warnings;
    /// The scene as a meff scene file (meff_scene 1), for `meff import`; empty for meff files.
    std::string meffText;
};

enum class SceneFormat
{
    Auto,    ///< decided by the content: a JSON object with "meff_scene" is meff's, one with
             ///< b2dJson's world fields ("body", "joint", "gravity", ...) is b2dJson
    Meff,    ///< docs/scene-format.md
    B2dJson, ///< R.U.B.E.'s export
};

/// How a level authored for Box2D 2.3 (what R.U.B.E. targets) is read where 2.3 and 2.4.1
/// differ (docs/b2djson.md, "Box2D 2.3 levels"). A level meff exported is read as 2.4.1 wrote
/// it whatever these say.
struct B2dJsonImportOptions
{
    /// Box2D 2.3's chains, and its edges with ghost vertices, collide on both sides; 2.4.1's
    /// are one-sided. true (default): each chain becomes two-sided segments, one per edge (and
    /// a ghosted edge a two-sided segment), as authored; false: 2.4.1's one-sided chains.
    bool twoSidedChains = true;
    /// Box2D 2.3 sizes the springs of distance (`frequency`), wheel (`springFrequency`) and
    /// weld (`frequency`) joints from the joint's effective mass, 2.4.1 from the bodies'
    /// masses. true (default): keep 2.3's stiffness and damping (at the level's pose): the
    /// frequency and damping ratio are rescaled so that 2.4.1's sizing gives them; false: the
    /// level's numbers as 2.4.1 reads them.
    bool springsAs23 = true;
};

/// True when `text` is a JSON object without "meff_scene" that has one of b2dJson's world
/// fields. Text that is not JSON is not b2dJson (the meff loader then says why).
bool LooksLikeB2dJson(std::string_view text);

/// Converts a b2dJson level to a scene. Throws SceneError listing every problem, each naming
/// `sourcePath` and the JSON path in the level.
/// Each choice of `options` where the level uses it is said in one warning line.
LoadedScene ImportB2dJson(std::string_view text, const std::string& sourcePath,
                          const SceneLimits& limits = {}, const B2dJsonImportOptions& options = {});

/// Reads a scene file in `format` (Auto: by its content); `options` for a b2dJson level.
/// Throws SceneError.
LoadedScene LoadSceneFile(const std::string& path, SceneFormat format = SceneFormat::Auto,
                          const SceneLimits& limits = {}, const B2dJsonImportOptions& options = {});

struct B2dJsonExportOptions
{
    /// Write numbers that are exactly floats as strings of their IEEE bits in hex (b2dJson's
    /// compact form: 1.5f is "3FC00000"), except 0 and 1, which stay numbers; other numbers in
    /// decimal. Default: every number in decimal, with enough digits to read back exactly.
    bool hexFloats = false;
};

/// The scene as b2dJson text. Throws SceneError when the scene cannot be built (it must be one
/// the loader accepted).
std::string ExportB2dJson(const Scene& scene, const B2dJsonExportOptions& options = {});

} // namespace meff
