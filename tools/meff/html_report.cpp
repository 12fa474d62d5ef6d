// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "html_report.h"

#include "junit.h"
#include "output_file.h"

#include "meff/box2d_mirror.h"
#include "meff/render.h"

#include "meff_version.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>

namespace meff::cli
{

namespace
{

std::string Number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

std::string Fixed(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    return text;
}

/// The plot's quantities: name, colour, and each frame's error over its allowance.
struct Series
{
    const char* name;
    const char* colour;
    double (*ratio)(const validation::FrameErrors&, const validation::Tolerances&);
};

const Series kSeries[] = {
    {"position", "#1f77b4",
     [](const validation::FrameErrors& f, const validation::Tolerances& t)
     { return f.position / t.position; }},
    {"angle", "#ff7f0e",
     [](const validation::FrameErrors& f, const validation::Tolerances& t)
     { return f.angle / t.angle; }},
    {"velocity", "#2ca02c",
     [](const validation::FrameErrors& f, const validation::Tolerances& t)
     { return f.velocity / t.velocity; }},
    {"contact impulse", "#d62728",
     [](const validation::FrameErrors& f, const validation::Tolerances&)
     { return f.contactRatio; }},
    {"joint impulse", "#9467bd",
     [](const validation::FrameErrors& f, const validation::Tolerances&) { return f.jointRatio; }},
};

/// The body a divergence is about: the first quantity that exceeded names it.
int DivergingBody(const Scene& scene, const validation::FrameErrors& errors,
                  const BuiltScene& built)
{
    const auto dynamicOf = [&](int a, int b)
    { return a >= 0 && scene.bodies[std::size_t(a)].type != BodyType::Static ? a : b; };
    for (const std::string& quantity : errors.exceeded)
    {
        if (quantity == "angle" && errors.angleBody >= 0)
        {
            return errors.angleBody;
        }
        if (quantity == "velocity" && errors.velocityBody >= 0)
        {
            return errors.velocityBody;
        }
        if (quantity == "contact_impulse" && errors.contact)
        {
            return dynamicOf(int(errors.contact->bodyA), int(errors.contact->bodyB));
        }
        if (quantity == "joint_impulse" && errors.joint >= 0)
        {
            const SceneJoint& joint = scene.joints[std::size_t(errors.joint)];
            const std::optional<std::size_t> b =
                built.SceneIndexOf(built.bodyByName.at(joint.bodyB));
            if (b)
            {
                return int(*b);
            }
        }
    }
    return errors.positionBody;
}

/// A point on the outline of `body`'s first shape (a polygon's first vertex, a circle's
/// rightmost point, a segment's first end), where both engines' outlines show side by side;
/// the centre of mass when it has no such shape.
Vec2 OutlinePoint(const World& world, BodyId body)
{
    for (const ShapeId shape : world.GetShapes(body))
    {
        switch (world.GetShapeType(shape))
        {
        case ShapeType::Polygon:
            return world.GetWorldPoint(body, world.GetPolygon(shape).vertices[0]);
        case ShapeType::Circle:
        {
            const Circle& circle = world.GetCircle(shape);
            return world.GetWorldPoint(body, circle.center + Vec2{circle.radius, 0});
        }
        case ShapeType::Segment:
            return world.GetWorldPoint(body, world.GetSegment(shape).point1);
        default:
            break;
        }
    }
    return world.GetWorldCenter(body);
}

/// A camera on `body` as the world has it now. Three body sizes across when the engines are
/// that far apart (or more); otherwise closer, on a point of its outline, so that a
/// difference of `apart` metres is about a tenth of the view (at least 2 cm across).
render::Camera CameraOn(const World& world, BodyId body, double apart)
{
    AABB box{world.GetWorldCenter(body), world.GetWorldCenter(body)};
    for (const ShapeId shape : world.GetShapes(body))
    {
        const AABB fat = world.GetShapeFatAABB(shape);
        box.lowerBound = Vec2{std::min(box.lowerBound.x, fat.lowerBound.x),
                              std::min(box.lowerBound.y, fat.lowerBound.y)};
        box.upperBound = Vec2{std::max(box.upperBound.x, fat.upperBound.x),
                              std::max(box.upperBound.y, fat.upperBound.y)};
    }
    const Vec2 extents = box.GetExtents();
    const double wide = 6 * double(std::max(extents.x, extents.y)); // three sizes
    const double close = std::max(10 * apart, 0.02);
    render::Camera camera;
    camera.center = close < wide ? OutlinePoint(world, body) : box.GetCenter();
    camera.height = Real(std::min(wide, close));
    return camera;
}

std::string StatusWord(const std::string& status)
{
    return status == "passed"    ? "PASS"
           : status == "failed"  ? "FAIL"
           : status == "skipped" ? "SKIP"
                                 : "ERROR";
}

} // namespace

std::string ErrorPlotSvg(const validation::ValidationResult& result)
{
    if (result.perFrame.empty())
    {
        return {};
    }
    constexpr int kWidth = 640;
    constexpr int kHeight = 220;
    constexpr int kLeft = 48;
    constexpr int kRight = 120; // the legend
    constexpr int kTop = 10;
    constexpr int kBottom = 28;
    constexpr double kFloor = -6; // ratios below 1e-6 (and exact zeros) sit on the floor
    const int plotWidth = kWidth - kLeft - kRight;
    const int plotHeight = kHeight - kTop - kBottom;
    const int frames = result.perFrame.back().frame;
    double top = 1; // log10 of the largest ratio shown, at least the tolerance's decade
    for (const validation::FrameErrors& errors : result.perFrame)
    {
        for (const Series& series : kSeries)
        {
            const double ratio = series.ratio(errors, result.tolerances);
            if (std::isfinite(ratio) && ratio > 0)
            {
                top = std::max(top, std::ceil(std::log10(ratio)));
            }
        }
    }
    const auto x = [&](double frame)
    { return kLeft + (frames > 0 ? frame / frames : 0.0) * plotWidth; };
    const auto y = [&](double ratio)
    {
        const double level =
            std::isfinite(ratio) ? (ratio > 0 ? std::max(std::log10(ratio), kFloor) : kFloor) : top;
        return kTop + (top - level) / (top - kFloor) * plotHeight;
    };
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" width=\"" +
                      std::to_string(kWidth) + "\" height=\"" + std::to_string(kHeight) +
                      "\" viewBox=\"0 0 " + std::to_string(kWidth) + " " + std::to_string(kHeight) +
                      "\" role=\"img\"><title>errors over " + "allowance, frames 0 to " +
                      std::to_string(frames) + "</title>";
    svg += "<rect x=\"" + std::to_string(kLeft) + "\" y=\"" + std::to_string(kTop) + "\" width=\"" +
           std::to_string(plotWidth) + "\" height=\"" + std::to_string(plotHeight) +
           "\" fill=\"#fff\" stroke=\"#999\"/>";
    for (double level = kFloor; level <= top; level += 1)
    {
        const double at = y(std::pow(10.0, level));
        svg += "<text x=\"" + std::to_string(kLeft - 4) + "\" y=\"" + Fixed(at + 4) +
               "\" text-anchor=\"end\" font-size=\"10\">1e" + std::to_string(int(level)) +
               "</text>";
    }
    // The allowance: a ratio above 1 exceeds its tolerance.
    svg += "<line x1=\"" + std::to_string(kLeft) + "\" x2=\"" + std::to_string(kLeft + plotWidth) +
           "\" y1=\"" + Fixed(y(1)) + "\" y2=\"" + Fixed(y(1)) +
           "\" stroke=\"#c00\" stroke-dasharray=\"4 3\"/>";
    const auto vertical = [&](int frame, const char* colour, const std::string& label)
    {
        svg += "<line x1=\"" + Fixed(x(frame)) + "\" x2=\"" + Fixed(x(frame)) + "\" y1=\"" +
               std::to_string(kTop) + "\" y2=\"" + std::to_string(kTop + plotHeight) +
               "\" stroke=\"" + colour + "\"/><text x=\"" + Fixed(x(frame) + 3) + "\" y=\"" +
               std::to_string(kTop + 12) + "\" font-size=\"10\" fill=\"" + colour + "\">" + label +
               "</text>";
    };
    if (result.chaotic)
    {
        vertical(result.horizonFrames, "#777", "horizon");
    }
    if (result.divergenceFrame)
    {
        vertical(*result.divergenceFrame, "#c00",
                 "frame " + std::to_string(*result.divergenceFrame));
    }
    // One point per pixel column at most: the largest ratio of the frames it covers.
    int legend = 0;
    for (const Series& series : kSeries)
    {
        std::string points;
        int column = -1;
        double largest = 0;
        const auto flush = [&]
        {
            if (column >= 0)
            {
                points += std::to_string(column) + "," + Fixed(y(largest)) + " ";
            }
        };
        for (const validation::FrameErrors& errors : result.perFrame)
        {
            const int at = int(std::lround(x(errors.frame)));
            const double ratio = series.ratio(errors, result.tolerances);
            if (at != column)
            {
                flush();
                column = at;
                largest = ratio;
            }
            else if (!(ratio <= largest))
            {
                largest = ratio;
            }
        }
        flush();
        svg += "<polyline fill=\"none\" stroke=\"" + std::string(series.colour) +
               "\" stroke-width=\"1.2\" points=\"" + points + "\"/>";
        const int legendY = kTop + 12 + 16 * legend++;
        svg += "<line x1=\"" + std::to_string(kWidth - kRight + 8) + "\" x2=\"" +
               std::to_string(kWidth - kRight + 24) + "\" y1=\"" + std::to_string(legendY - 4) +
               "\" y2=\"" + std::to_string(legendY - 4) + "\" stroke=\"" + series.colour +
               "\" stroke-width=\"2\"/><text x=\"" + std::to_string(kWidth - kRight + 28) +
               "\" y=\"" + std::to_string(legendY) + "\" font-size=\"11\">" + series.name +
               "</text>";
    }
    svg += "<text x=\"" + std::to_string(kLeft) + "\" y=\"" + std::to_string(kHeight - 8) +
           "\" font-size=\"11\">frame 0</text><text x=\"" + std::to_string(kLeft + plotWidth) +
           "\" y=\"" + std::to_string(kHeight - 8) + "\" font-size=\"11\" text-anchor=\"end\">" +
           "frame " + std::to_string(frames) + "</text><text x=\"" +
           std::to_string(kLeft + plotWidth / 2) + "\" y=\"" + std::to_string(kHeight - 8) +
           "\" font-size=\"11\" text-anchor=\"middle\">error / allowance (dashed: 1, the " +
           "tolerance)</text></svg>";
    return svg;
}

std::vector<ReportImage> DrawDivergenceFrames(const Scene& scene,
                                              const validation::ValidationResult& result,
                                              const std::filesystem::path& reportDirectory,
                                              const std::string& folder)
{
    if (!result.divergenceFrame || result.perFrame.empty())
    {
        return {};
    }
    const int divergence = *result.divergenceFrame;
    // Stepped again as validation::Validate stepped it.
    BuiltScene built = BuildWorld(scene);
    SolverSettings solver = built.world.GetSolverSettings();
    solver.blockSolver = result.blockSolver;
    solver.velocityIterations = result.meffVelocityIterations;
    built.world.SetSolverSettings(solver);
    validation::Box2DMirror mirror(scene, result.blockSolver);
    const validation::FrameErrors& errors = result.perFrame.at(std::size_t(divergence));
    const int body = DivergingBody(scene, errors, built);
    if (body < 0)
    {
        return {};
    }
    const BodyId id = built.bodies[std::size_t(body)];

    // One OSMesa context at a time: levels are reported from several threads.
    static std::mutex drawing;
    const std::lock_guard lock(drawing);
    render::OffscreenRenderer renderer(480, 360);
    std::vector<ReportImage> images;
    const auto draw = [&](int frame, const char* name)
    {
        const b2Vec2 box2d = mirror.Body(std::size_t(body))->GetPosition();
        const Vec2 position = built.world.GetPosition(id);
        const double apart = std::hypot(double(position.x) - box2d.x, double(position.y) - box2d.y);
        render::FrameOptions options;
        options.camera = CameraOn(built.world, id, apart);
        options.flags.shapes = true;
        options.overlay = [&](DebugDraw& drawer) { mirror.Draw(drawer, validation::kBox2DColor); };
        options.overlayLegend.push_back({validation::kBox2DColor, "Box2D 2.4.1"});
        options.caption = "frame " + std::to_string(frame) + ": " +
                          validation::DescribeBody(scene, body) +
                          ", meff - Box2D = " + Number(apart) + " m";
        const render::Image image = render::RenderFrame(renderer, built.world, options);
        const std::string file = folder + "/" + name;
        OutputFile out((reportDirectory / file).string());
        const std::vector<std::uint8_t> png = render::EncodePng(image);
        std::fwrite(png.data(), 1, png.size(), out.Stream());
        out.Commit();
        images.push_back({file, options.caption});
    };
    const Real dt = Real(scene.world.dt);
    for (int frame = 1; frame < divergence; ++frame)
    {
        built.Step(dt);
        mirror.Step();
    }
    if (divergence > 0)
    {
        draw(divergence - 1, "before.png");
        built.Step(dt);
        mirror.Step();
    }
    draw(divergence, "at.png");
    return images;
}

void WriteHtmlReport(const std::string& directory, const std::vector<ReportRow>& rows,
                     const std::string& reference)
{
    int counts[4] = {};
    for (const ReportRow& row : rows)
    {
        counts[row.status == "passed"    ? 0
               : row.status == "failed"  ? 1
               : row.status == "skipped" ? 2
                                         : 3]++;
    }
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                       "<title>meff validate</title><style>"
                       "body{font-family:sans-serif;margin:1.5em;color:#222}"
                       "table{border-collapse:collapse;font-size:13px}"
                       "th,td{border:1px solid #ccc;padding:3px 6px;text-align:right}"
                       "th{background:#f0f0f0}td.l{text-align:left}"
                       "tr.passed td.s{background:#d8f5d8}tr.failed td.s{background:#f8d0d0}"
                       "tr.skipped td.s{background:#eee}tr.error td.s{background:#f8e0b0}"
                       "pre{background:#f7f7f7;padding:6px;white-space:pre-wrap;font-size:12px}"
                       "figure{display:inline-block;margin:4px}figcaption{font-size:12px}"
                       "section{border-top:1px solid #ccc;margin-top:1em}</style></head><body>\n";
    html += "<h1>meff validate</h1><p>meff " + std::string(MEFF_VERSION) + " against " +
            XmlEscape(reference) + ": " + std::to_string(rows.size()) + " levels, " +
            std::to_string(counts[0]) + " passed, " + std::to_string(counts[1]) + " failed, " +
            std::to_string(counts[2]) + " skipped, " + std::to_string(counts[3]) +
            " could not be loaded. Errors are the largest over the run (m, rad, m/s, N·s)" +
            (reference == kBox2DReference
                 ? "; blue outlines in the pictures are Box2D's bodies over meff's.</p>\n"
                 : ".</p>\n");
    html += "<table id=\"levels\"><thead><tr><th>outcome</th><th>level</th><th>scene</th>"
            "<th>frames</th><th>first divergent frame</th><th>position</th><th>angle</th>"
            "<th>velocity</th><th>contact impulse</th><th>joint impulse</th></tr></thead>"
            "<tbody>\n";
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const ReportRow& row = rows[i];
        html += "<tr class=\"" + row.status + "\"><td class=\"s\">" + StatusWord(row.status) +
                "</td><td class=\"l\"><a href=\"#level-" + std::to_string(i) + "\">" +
                XmlEscape(row.path) + "</a></td><td class=\"l\">" + XmlEscape(row.scene) + "</td>";
        if (row.ran)
        {
            html += "<td>" + std::to_string(row.frames) + "</td><td>" +
                    (row.divergenceFrame ? std::to_string(*row.divergenceFrame) : "-") +
                    "</td><td>" + Number(row.position) + "</td><td>" + Number(row.angle) +
                    "</td><td>" + Number(row.velocity) + "</td><td>" + Number(row.contactImpulse) +
                    "</td><td>" + Number(row.jointImpulse) + "</td>";
        }
        else
        {
            html += "<td colspan=\"7\" class=\"l\">not compared</td>";
        }
        html += "</tr>\n";
    }
    html += "</tbody></table>\n";
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const ReportRow& row = rows[i];
        html += "<section id=\"level-" + std::to_string(i) + "\"><h2>" + StatusWord(row.status) +
                " " + XmlEscape(row.path) + "</h2>";
        if (!row.divergence.empty())
        {
            html += "<p>" + XmlEscape(row.divergence) + "</p>";
        }
        html += "<pre>" + XmlEscape(row.text) + "</pre>";
        for (const ReportImage& image : row.images)
        {
            html += "<figure><img src=\"" + XmlEscape(image.file) + "\" alt=\"" +
                    XmlEscape(image.caption) + "\" width=\"480\" height=\"360\"><figcaption>" +
                    XmlEscape(image.caption) + "</figcaption></figure>";
        }
        html += row.plotSvg;
        if (!row.directory.empty())
        {
            html += "<p><a href=\"" + XmlEscape(row.directory) +
                    "/summary.json\">summary.json</a>" +
                    (row.ran ? " · <a href=\"" + XmlEscape(row.directory) +
                                   "/divergence.csv\">divergence.csv</a>"
                             : std::string()) +
                    "</p>";
        }
        html += "</section>\n";
    }
    // Marks each picture the browser decoded (its width), for a headless check of the page.
    html += "<script>window.addEventListener('load',function(){for(const i of document.images)"
            "{if(i.complete&&i.naturalWidth>0)i.setAttribute('data-loaded',String(i.naturalWidth));"
            "}});</script>\n</body></html>\n";
    OutputFile file((std::filesystem::path(directory) / "index.html").string());
    std::fputs(html.c_str(), file.Stream());
    file.Commit();
}

} // namespace meff::cli
