// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The page of `meff validate --report DIR`: DIR/index.html, one row per level (its outcome, the
// first divergent frame, the largest errors), and under the table each level's errors plotted
// over the run (inline SVG, drawn here: no plotting program) and, for a level that diverged,
// the frame before and the frame at the divergence zoomed on the body that diverged, meff's
// bodies drawn with Box2D 2.4.1's outlines over them (PNG files in the level's folder). The
// page needs nothing but the files beside it: it works opened from disk.
#pragma once

#include "meff/scene.h"
#include "meff/validation.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace meff::cli
{

/// A picture of a level's run: its file (relative to the report folder) and what it shows.
struct ReportImage
{
    std::string file;
    std::string caption;
};

/// One level of the page.
struct ReportRow
{
    std::string status;    ///< "passed", "failed", "skipped" or "error"
    std::string path;      ///< the level's file, as given
    std::string scene;     ///< the scene's name (empty when it did not load)
    std::string directory; ///< its folder under the report folder
    std::string text;      ///< what validate printed about it (several lines)
    bool ran = false;      ///< compared: the columns below mean something
    int frames = 0;
    std::optional<int> divergenceFrame;
    std::string divergence; ///< what exceeded its tolerance there, and where
    double position = 0;    ///< largest errors over the run
    double angle = 0;
    double velocity = 0;
    double contactImpulse = 0;
    double jointImpulse = 0;
    std::string plotSvg; ///< the errors over the run (ErrorPlotSvg), or empty
    std::vector<ReportImage> images;
};

/// The run's errors over its frames as an inline SVG element: each quantity divided by its
/// allowance (position, angle, velocity by their tolerances; contact and joint impulses by
/// their ratios), on a log scale, with the tolerance (ratio 1), the divergence frame and a
/// chaotic scene's horizon marked. Empty when there are no frames.
std::string ErrorPlotSvg(const validation::ValidationResult& result);

/// Draws the frame before and the frame at the divergence (one frame for a divergence at
/// frame 0) into `folder` as before.png and at.png: the scene stepped again, meff as World::Draw
/// draws it and Box2D 2.4.1's bodies as outlines over it, the camera on the body that diverged,
/// close enough that the difference shows. `run` must be what the comparison ran with. Returns
/// each image, its file relative to `reportDirectory`. Throws render::RenderError or
/// std::runtime_error when it cannot be drawn or written.
std::vector<ReportImage> DrawDivergenceFrames(const Scene& scene,
                                              const validation::ValidationResult& result,
                                              const std::filesystem::path& reportDirectory,
                                              const std::string& folder);

/// What the levels were compared with, unless a baseline: the page says so.
inline const std::string kBox2DReference = "Box2D 2.4.1";

/// Writes DIRECTORY/index.html whole (or not at all); throws std::runtime_error when it cannot.
/// `reference` says what the levels were compared with ("its baselines in DIR", say).
void WriteHtmlReport(const std::string& directory, const std::vector<ReportRow>& rows,
                     const std::string& reference = kBox2DReference);

} // namespace meff::cli
