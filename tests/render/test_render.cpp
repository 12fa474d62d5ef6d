// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The off-screen renderer: the same world gives the same bytes, and pixels mean what they
// should (a circle is where the camera says, a body moving right moves right in the image).
#include "meff/render.h"
#include "meff/scene.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace meff;
using namespace meff::render;

namespace
{

constexpr DrawColor kRed{1, 0, 0};

/// No gravity, one dynamic circle of radius 0.5 m at `position` moving at `velocity`.
World OneCircle(Vec2 position, Vec2 velocity = {})
{
    World world{WorldDef{.gravity = {0, 0}}};
    const BodyId body = world.CreateBody(
        BodyDef{.type = BodyType::Dynamic, .position = position, .linearVelocity = velocity});
    world.CreateShape(body, ShapeDef{}, Circle{{0, 0}, Real(0.5)});
    return world;
}

/// A camera 10 m tall centred on the origin: 20 pixels per metre in a 200×200 image, so world
/// (x, y) lands on pixel (100 + 20x, 100 − 20y).
FrameOptions RedOptions()
{
    FrameOptions options;
    options.camera = Camera{{0, 0}, 10};
    options.flags.colors.dynamicBody = kRed;
    return options;
}

/// The colour legend's band along the bottom edge (9-pixel text and its margins in the small
/// test images), where a swatch of each body colour is drawn.
constexpr int kLegendBand = 30;

/// The mean column of the pixels that carry the circle's fill colour above the legend, or -1 if
/// none do.
double FillCentroidX(const Image& image, Rgb fill)
{
    double sum = 0;
    int count = 0;
    for (int y = 0; y < image.height - kLegendBand; ++y)
    {
        for (int x = 0; x < image.width; ++x)
        {
            if (image.At(x, y) == fill)
            {
                sum += x;
                ++count;
            }
        }
    }
    return count > 0 ? sum / count : -1;
}

std::vector<std::uint8_t> RenderScenePng(const Scene& scene, int steps, const DrawFlags& flags)
{
    BuiltScene built = BuildWorld(scene);
    for (int i = 0; i < steps; ++i)
    {
        built.world.Step(Real(scene.world.dt));
    }
    // A fresh context each time: nothing may carry over from an earlier frame or renderer.
    OffscreenRenderer renderer(320, 240);
    FrameOptions options;
    options.camera = FitCamera(built.world, 320, 240);
    options.flags = flags;
    options.caption = scene.name + "  frame " + std::to_string(steps);
    options.legendImpulse = 1.0;
    return EncodePng(RenderFrame(renderer, built.world, options));
}

} // namespace

TEST_CASE("Rendering the same scene twice gives byte-identical PNGs", "[render]")
{
    const Scene scene = LoadScene(
        (std::filesystem::path(MEFF_SOURCE_DIR) / "samples/scenes/pyramid20.json").string());
    const DrawFlags flags{
        .joints = true, .contacts = true, .contactImpulses = true, .jointReactions = true};
    const std::vector<std::uint8_t> first = RenderScenePng(scene, 30, flags);
    const std::vector<std::uint8_t> second = RenderScenePng(scene, 30, flags);
    REQUIRE(first.size() > 1000);
    CHECK(first == second);
    // And the picture does depend on the state: a later frame differs.
    CHECK(RenderScenePng(scene, 31, flags) != first);
}

TEST_CASE("A red circle is drawn where the camera puts it", "[render]")
{
    const World world = OneCircle({2, 1}); // pixel (140, 80), radius 10 pixels
    OffscreenRenderer renderer(200, 200);
    const Image image = RenderFrame(renderer, world, RedOptions());
    REQUIRE(image.width == 200);
    REQUIRE(image.height == 200);

    const Rgb fill = FillColor(kRed);
    // The centre itself carries the angle line (red, along +x); just beside it is fill.
    CHECK(image.At(140, 80 + 4) == fill);
    CHECK(image.At(140, 80 - 5) == fill);
    CHECK(image.At(140 - 5, 80 + 2) == fill);
    const Rgb centre = image.At(142, 80);
    CHECK(int(centre.r) > int(centre.g) + 60);
    // The outline is red, the colour DebugDraw was given: on the circle's left edge.
    const Rgb edge = image.At(130, 80);
    CHECK(int(edge.r) > int(edge.g) + 60);
    // Away from it: background.
    CHECK(image.At(140 + 15, 80) == kBackground);
    CHECK(image.At(140, 80 + 15) == kBackground);
    CHECK(image.At(20, 160) == kBackground);
    CHECK(image.At(199, 199 - kLegendBand) == kBackground);
    // The fill's centroid is the circle's centre, to a fraction of a pixel.
    CHECK(FillCentroidX(image, fill) == Approx(140).margin(1.0));
}

TEST_CASE("A capsule and a rounded box are drawn with round ends and corners", "[render]")
{
    // The camera of RedOptions: world (x, y) on pixel (100 + 20x, 100 − 20y).
    World world{WorldDef{.gravity = {0, 0}}};
    // A capsule from (−3, 1) to (−1, 1), radius 0.5: core from pixel (40, 80) to (80, 80),
    // radius 10 pixels.
    const BodyId capsule =
        world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {-2, 1}});
    world.CreateShape(capsule, ShapeDef{}, Capsule{{-1, 0}, {1, 0}, Real(0.5)});
    // A 1 m square core rounded by 0.25 m at (2, −1): core corners 10 pixels from the centre
    // pixel (140, 120), rounding 5 pixels.
    Polygon rounded = MakeBox(Real(0.5), Real(0.5));
    rounded.radius = Real(0.25);
    const BodyId box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {2, -1}});
    world.CreateShape(box, ShapeDef{}, rounded);
    OffscreenRenderer renderer(200, 200);
    const Image image = RenderFrame(renderer, world, RedOptions());
    const Rgb fill = FillColor(kRed);
    // The capsule: fill beside its axis line and inside a cap; outside the cap, though inside
    // its bounding box (12.7 pixels from the cap's centre), background.
    CHECK(image.At(60, 80 + 5) == fill);
    CHECK(image.At(60, 80 - 5) == fill);
    CHECK(image.At(34, 80 + 2) == fill);
    CHECK(image.At(31, 71) == kBackground);
    CHECK(image.At(89, 89) == kBackground);
    CHECK(image.At(60, 80 + 13) == kBackground);
    // The rounded box: fill in the band beyond each face; the corners of its bounding square
    // background (pixel (x, y) covers [x, x + 1) × [y, y + 1): the centres of pixels (154, 134)
    // and (125, 105) are 6.4 pixels from the core's corners, beyond the 5-pixel rounding).
    CHECK(image.At(140 + 13, 120 + 3) == fill);
    CHECK(image.At(140 - 3, 120 - 13) == fill);
    CHECK(image.At(140 + 14, 120 + 14) == kBackground);
    CHECK(image.At(140 - 15, 120 - 15) == kBackground);
}

TEST_CASE("A body that moves right moves right in the image", "[render]")
{
    World world = OneCircle({-2, 0}, {3, 0});
    OffscreenRenderer renderer(200, 200);
    const FrameOptions options = RedOptions();
    const Rgb fill = FillColor(kRed);

    const double before = FillCentroidX(RenderFrame(renderer, world, options), fill);
    for (int i = 0; i < 30; ++i)
    {
        world.Step(Real(1) / Real(60));
    }
    const double after = FillCentroidX(RenderFrame(renderer, world, options), fill);
    REQUIRE(before > 0);
    REQUIRE(after > 0);
    // 3 m/s for half a second: 1.5 m, 30 pixels to the right.
    CHECK(before == Approx(100 - 40).margin(1.0));
    CHECK(after - before == Approx(30).margin(1.0));
}

TEST_CASE("The camera fits the bodies and keeps the image's aspect", "[render]")
{
    World world{WorldDef{}};
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, Segment{{-10, 0}, {10, 0}});
    const BodyId box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {0, 3}});
    world.CreateShape(box, ShapeDef{}, MakeBox(1, 1));
    const Camera camera = FitCamera(world, 400, 200);
    // 20 m wide at 2:1 needs 10 m of height, plus the margin; centred on the bounds.
    CHECK(double(camera.height) > 10);
    CHECK(double(camera.height) < 14);
    CHECK(double(camera.center.x) == Approx(0).margin(1e-6));
    CHECK(double(camera.center.y) == Approx(2).margin(0.02));
}

TEST_CASE("Renderer sizes outside 1..8192 are refused", "[render]")
{
    CHECK_THROWS_AS(OffscreenRenderer(0, 100), RenderError);
    CHECK_THROWS_AS(OffscreenRenderer(100, 0), RenderError);
    CHECK_THROWS_AS(OffscreenRenderer(kMaxImageSize + 1, 100), RenderError);
    const OffscreenRenderer one(1, 1);
    CHECK(one.Supersample() >= 1);
}

namespace
{

/// The pixels `text` changes on a white image, as a string of bytes (to compare drawings).
std::vector<std::uint8_t> TextPixels(const std::string& text, int pixelSize, Image* out = nullptr)
{
    Image image(60, 40, Rgb{255, 255, 255});
    DrawText(image, 2, 2, text, Rgb{0, 0, 0}, pixelSize);
    if (out != nullptr)
    {
        *out = image;
    }
    return image.pixels;
}

/// Whether any pixel in rows [top, bottom) of the image has colour `color`.
bool HasColorInRows(const Image& image, int top, int bottom, Rgb color)
{
    for (int y = std::max(0, top); y < std::min(image.height, bottom); ++y)
    {
        for (int x = 0; x < image.width; ++x)
        {
            if (image.At(x, y) == color)
            {
                return true;
            }
        }
    }
    return false;
}

} // namespace

TEST_CASE("Text is drawn in DejaVu Sans through FreeType", "[render]")
{
    CHECK(FontPath().find("DejaVuSans.ttf") != std::string::npos);
    CHECK(TextWidth("", 14) == 0);
    // A proportional font: narrow letters take less room than wide ones (a pixel font gives
    // every character the same cell).
    CHECK(TextWidth("il", 14) < TextWidth("WM", 14));
    CHECK(TextWidth("WM", 28) > TextWidth("WM", 14));
    // DejaVu's line at 14 px per em: ascender to descender about 1.16 em.
    CHECK(TextHeight(14) >= 15);
    CHECK(TextHeight(14) <= 18);

    // The pixel font drew 'g' like '9' and 'p' like 'ρ'; these glyphs differ.
    CHECK(TextPixels("g", 14) != TextPixels("9", 14));
    CHECK(TextPixels("p", 14) != TextPixels("\xCF\x81", 14)); // ρ, which DejaVu has
    // Deterministic, anti-aliased (grey levels between black and white), and only where the
    // text is.
    Image image;
    CHECK(TextPixels("Ag", 14, &image) == TextPixels("Ag", 14));
    bool grey = false;
    bool dark = false;
    for (int y = 0; y < image.height; ++y)
    {
        for (int x = 0; x < image.width; ++x)
        {
            const Rgb pixel = image.At(x, y);
            dark = dark || pixel.r < 60;
            grey = grey || (pixel.r > 60 && pixel.r < 200);
            if (x >= 2 + TextWidth("Ag", 14) + 2 || y >= 2 + TextHeight(14) + 2)
            {
                CHECK(pixel == Rgb{255, 255, 255});
            }
        }
    }
    CHECK(dark);
    CHECK(grey);
}

TEST_CASE("The legend shows a swatch for every colour the frame uses, and only those", "[render]")
{
    // A static ground and one dynamic box, awake: the legend has "static" and "dynamic" and
    // nothing else (no sleeping, joint or contact colours).
    World world{WorldDef{}};
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, MakeBox(5, 0.5f));
    const BodyId box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {0, 3}});
    world.CreateShape(box, ShapeDef{}, MakeBox(0.5f, 0.5f));
    OffscreenRenderer renderer(320, 240);
    FrameOptions options;
    options.camera = Camera{{0, 1.5f}, 10}; // the bodies well above the bottom edge
    const DrawPalette& palette = options.flags.colors;
    // The legend's rows: the bottom 30 pixels (text of 9 px per em plus margins), where the
    // camera puts no body.
    const auto legendHas = [&](const Image& image, const DrawColor& color)
    { return HasColorInRows(image, image.height - 30, image.height, FillColor(color)); };
    const Image plain = RenderFrame(renderer, world, options);
    CHECK(legendHas(plain, palette.staticBody));
    CHECK(legendHas(plain, palette.dynamicBody));
    CHECK_FALSE(legendHas(plain, palette.sleepingBody));
    CHECK_FALSE(legendHas(plain, palette.joint));
    CHECK_FALSE(legendHas(plain, palette.contactPoint));

    // An overlay's colour is explained when the overlay draws it, with its label.
    const DrawColor blue{0.0f, 0.4f, 1.0f};
    options.overlay = [&](DebugDraw& draw) { draw.DrawSegment({-1, 0}, {1, 0}, blue); };
    options.overlayLegend = {{blue, "Box2D 2.4.1"}};
    CHECK(legendHas(RenderFrame(renderer, world, options), blue));
    // ...and not when it does not.
    options.overlay = nullptr;
    CHECK_FALSE(legendHas(RenderFrame(renderer, world, options), blue));

    // Drawing from a recording gives the very bytes drawing from the world gives.
    DrawList drawing;
    world.Draw(drawing, options.flags);
    CHECK(RenderFrame(renderer, drawing, options).pixels ==
          RenderFrame(renderer, world, options).pixels);
}

TEST_CASE("PNGs round-trip exactly and are written whole", "[render]")
{
    Image image(7, 5);
    image.Set(3, 2, Rgb{10, 200, 30});
    const std::vector<std::uint8_t> bytes = EncodePng(image);
    const Image decoded = DecodePng(bytes);
    CHECK(decoded.width == 7);
    CHECK(decoded.height == 5);
    CHECK(decoded.pixels == image.pixels);

    const std::filesystem::path directory =
        std::filesystem::temp_directory_path() / "meff_render_test_png";
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
    const std::string path = (directory / "x.png").string();
    WritePng(path, image);
    CHECK(ReadPng(path).pixels == image.pixels);
    // Only the file itself: the temporary it was written through is gone.
    CHECK(std::distance(std::filesystem::directory_iterator(directory),
                        std::filesystem::directory_iterator()) == 1);
    CHECK_THROWS_AS(WritePng((directory / "missing" / "y.png").string(), image), RenderError);
    CHECK_THROWS_AS(DecodePng(std::vector<std::uint8_t>{1, 2, 3}), RenderError);
    std::filesystem::remove_all(directory);
}

TEST_CASE("Frames stitch side by side", "[render]")
{
    const std::vector<Image> frames = {Image(3, 2, Rgb{1, 1, 1}), Image(4, 3, Rgb{2, 2, 2})};
    const Image strip = StitchHorizontally(frames, 1);
    CHECK(strip.width == 8);
    CHECK(strip.height == 3);
    CHECK(strip.At(0, 0) == Rgb{1, 1, 1});
    CHECK(strip.At(3, 0) == kGapColor);
    CHECK(strip.At(4, 2) == Rgb{2, 2, 2});
    CHECK(strip.At(0, 2) == kGapColor);
}

TEST_CASE("NiceCeil picks 1, 2 or 5 times a power of ten", "[render]")
{
    CHECK(NiceCeil(0.7) == Approx(1));
    CHECK(NiceCeil(1) == Approx(1));
    CHECK(NiceCeil(1.2) == Approx(2));
    CHECK(NiceCeil(3) == Approx(5));
    CHECK(NiceCeil(0.031) == Approx(0.05));
    CHECK(NiceCeil(600) == Approx(1000));
}

namespace
{

/// The mean pixel (x, y), pixel centres at +0.5, of the pixels of colour `fill` above the
/// legend band; (-1, -1) when none.
Vec2 FillCentroid(const Image& image, Rgb fill)
{
    double sx = 0, sy = 0;
    int count = 0;
    for (int y = 0; y < image.height - kLegendBand; ++y)
    {
        for (int x = 0; x < image.width; ++x)
        {
            if (image.At(x, y) == fill)
            {
                sx += x + 0.5;
                sy += y + 0.5;
                ++count;
            }
        }
    }
    return count > 0 ? Vec2{Real(sx / count), Real(sy / count)} : Vec2{-1, -1};
}

std::string HexOf(Rgb color)
{
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", color.r, color.g, color.b);
    return text;
}

/// The value of attribute `name` in the first SVG element starting with `element` that has
/// `marker` in it, or empty.
std::string SvgAttribute(const std::string& svg, const std::string& element,
                         const std::string& marker, const std::string& name)
{
    for (std::size_t at = svg.find(element); at != std::string::npos;
         at = svg.find(element, at + 1))
    {
        const std::string tag = svg.substr(at, svg.find('>', at) - at);
        if (tag.find(marker) == std::string::npos)
        {
            continue;
        }
        const std::size_t value = tag.find(" " + name + "=\"");
        if (value == std::string::npos)
        {
            return {};
        }
        const std::size_t start = value + name.size() + 3;
        return tag.substr(start, tag.find('"', start) - start);
    }
    return {};
}

} // namespace

TEST_CASE("An SVG frame has the PNG's geometry", "[render]")
{
    // A red box 2 m square at (2, 1) and a red circle of radius 0.5 m at (-2, -1): under
    // RedOptions' camera, centres on pixels (140, 80) and (60, 120).
    World world{WorldDef{.gravity = {0, 0}}};
    const BodyId box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {2, 1}});
    world.CreateShape(box, ShapeDef{}, MakeBox(1, 1));
    const BodyId ball = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {-2, -1}});
    world.CreateShape(ball, ShapeDef{}, Circle{{0, 0}, Real(0.5)});
    FrameOptions options = RedOptions();
    options.caption = "svg & png";
    DrawList drawing;
    world.Draw(drawing, options.flags);
    OffscreenRenderer renderer(200, 200);
    const Image image = RenderFrame(renderer, drawing, options);
    const std::string svg = RenderSvg(drawing, options, 200, 200);
    CHECK(svg == RenderSvg(drawing, options, 200, 200)); // deterministic
    CHECK(svg.find("width=\"200\" height=\"200\"") != std::string::npos);
    CHECK(svg.find("svg &amp; png") != std::string::npos); // the caption, escaped

    const std::string fill = HexOf(FillColor(kRed));
    // The box: its four corners in the SVG are where the camera puts them, exactly; the PNG's
    // fill pixels centre on the same point. Tolerance half a pixel: the fill is the inside of
    // a 1-pixel outline drawn symmetrically about the edges, so its centroid is the polygon's
    // up to how the edges fall on the pixel grid.
    const std::string points = SvgAttribute(svg, "<polygon", "fill=\"" + fill, "points");
    CHECK(points == "120,100 160,100 160,60 120,60");
    // The circle.
    CHECK(SvgAttribute(svg, "<circle", "fill=\"" + fill, "cx") == "60");
    CHECK(SvgAttribute(svg, "<circle", "fill=\"" + fill, "cy") == "120");
    CHECK(SvgAttribute(svg, "<circle", "fill=\"" + fill, "r") == "10");
    // The PNG: each shape's fill pixels, split by the image's middle column (the box right of
    // it, the ball left).
    Image boxOnly = image, ballOnly = image;
    for (int y = 0; y < image.height; ++y)
    {
        for (int x = 0; x < image.width; ++x)
        {
            (x < 100 ? boxOnly : ballOnly).Set(x, y, kBackground);
            // The ball's angle line runs right from its centre along row 120: leave out the
            // rows around it (symmetric about the centre), which the line takes from the fill
            // on the right only.
            if (y >= 117 && y <= 122)
            {
                ballOnly.Set(x, y, kBackground);
            }
        }
    }
    const Vec2 boxCentre = FillCentroid(boxOnly, FillColor(kRed));
    const Vec2 ballCentre = FillCentroid(ballOnly, FillColor(kRed));
    CHECK(double(boxCentre.x) == Approx(140).margin(0.5));
    CHECK(double(boxCentre.y) == Approx(80).margin(0.5));
    CHECK(double(ballCentre.x) == Approx(60).margin(0.5));
    CHECK(double(ballCentre.y) == Approx(120).margin(0.5));
    // The line width is the PNG's (1 pixel at this size).
    CHECK(svg.find("stroke-width=\"1\"") != std::string::npos);
}

TEST_CASE("A camera following a body keeps it in the frame for the whole run", "[render]")
{
    // terrain_car: the car drives over hills past the scene's own fixed camera, which loses it.
    const Scene scene = LoadScene(
        (std::filesystem::path(MEFF_SOURCE_DIR) / "samples/scenes/terrain_car.json").string());
    BuiltScene built = BuildWorld(scene);
    const BodyId chassis = built.bodyByName.at("chassis");
    const int width = 640, height = 480;
    const double aspect = double(width) / height;
    REQUIRE(scene.camera);
    const Camera fixed{Vec2{Real(scene.camera->center.x), Real(scene.camera->center.y)},
                       Real(scene.camera->height)};
    FollowCamera follow(built.world, chassis, fixed.height, aspect);
    // The fraction of the view's half-size the body's box reaches from the centre: <= 1 is in
    // the frame. The projection, not pixels: the box against the camera's rectangle.
    const auto reach = [&](const Camera& camera)
    {
        const AABB box = *BodyBounds(built.world, chassis);
        const double halfHeight = 0.5 * double(camera.height);
        const double halfWidth = halfHeight * aspect;
        const double cx = double(camera.center.x), cy = double(camera.center.y);
        return std::max({(cx - double(box.lowerBound.x)) / halfWidth,
                         (double(box.upperBound.x) - cx) / halfWidth,
                         (cy - double(box.lowerBound.y)) / halfHeight,
                         (double(box.upperBound.y) - cy) / halfHeight});
    };
    double worstFollowed = reach(follow.Current());
    int lostByFixed = reach(fixed) > 1 ? 1 : 0;
    double largestMove = 0;
    const double dt = scene.world.dt;
    for (int frame = 1; frame <= scene.world.frames; ++frame)
    {
        built.Step(Real(dt));
        const Vec2 before = follow.Current().center;
        const Camera& camera = follow.Update(built.world, dt);
        worstFollowed = std::max(worstFollowed, reach(camera));
        lostByFixed += reach(fixed) > 1 ? 1 : 0;
        largestMove = std::max(largestMove, double((camera.center - before).Length()));
    }
    // Within the middle 80 % (plus float rounding of the centre) on every frame...
    CHECK(worstFollowed <= 0.8 + 1e-4);
    // ...where the scene's fixed camera loses the car on some frames (the test has teeth).
    CHECK(lostByFixed > 0);
    // Smooth: the camera never jumps; a step moves it less than 0.1 m (the car drives at a few
    // m/s, a few cm per 1/60 s step).
    CHECK(largestMove < 0.1);
}

TEST_CASE("Transparent frames, no caption or legend, the scale bar, wider lines", "[render]")
{
    const World world = OneCircle({2, 1});
    OffscreenRenderer renderer(200, 200);
    FrameOptions options = RedOptions();
    const Image opaque = RenderFrame(renderer, world, options);
    CHECK_FALSE(opaque.HasAlpha());
    // The scale bar: text-coloured pixels at the bottom right (200 px at 20 px/m: 2 m, 40 px).
    const auto textPixelsIn = [](const Image& image, int x0, int y0)
    {
        int count = 0;
        for (int y = y0; y < image.height; ++y)
        {
            for (int x = x0; x < image.width; ++x)
            {
                count += image.At(x, y) == kTextColor ? 1 : 0;
            }
        }
        return count;
    };
    CHECK(textPixelsIn(opaque, 120, 170) > 40);

    options.legend = false;
    const Image bare = RenderFrame(renderer, world, options);
    CHECK(textPixelsIn(bare, 0, 170) == 0);
    // Nothing but the circle: every pixel away from it is background.
    CHECK(bare.At(199, 199) == kBackground);
    CHECK(bare.At(5, 195) == kBackground);

    options.transparent = true;
    const Image clear = RenderFrame(renderer, world, options);
    REQUIRE(clear.HasAlpha());
    CHECK(clear.AlphaAt(5, 5) == 0);
    CHECK(clear.AlphaAt(140, 84) == 255);
    // The same colours where something is drawn, opaque.
    CHECK(clear.At(140, 84) == bare.At(140, 84));
    CHECK(clear.At(140, 84) == FillColor(kRed));
    // Edges are partly transparent (anti-aliased), not blended with a background colour.
    bool partial = false;
    for (int x = 125; x < 135; ++x)
    {
        partial = partial || (clear.AlphaAt(x, 80) > 0 && clear.AlphaAt(x, 80) < 255);
    }
    CHECK(partial);
    // The PNG keeps the alpha plane.
    const Image decoded = DecodePng(EncodePng(clear));
    CHECK(decoded.pixels == clear.pixels);
    CHECK(decoded.alpha == clear.alpha);

    CHECK(LineWidth(640, 480) == 1.0);
    CHECK(LineWidth(1920, 1080) == Approx(2.25));
}

TEST_CASE("NiceFloor picks 1, 2 or 5 times a power of ten", "[render]")
{
    CHECK(NiceFloor(1) == Approx(1));
    CHECK(NiceFloor(3) == Approx(2));
    CHECK(NiceFloor(7.5) == Approx(5));
    CHECK(NiceFloor(9.9) == Approx(5));
    CHECK(NiceFloor(0.7) == Approx(0.5));
    CHECK(NiceFloor(1.5) == Approx(1));
    CHECK(NiceFloor(20) == Approx(20));
}
