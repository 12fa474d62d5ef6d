// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Polygon construction, mass properties and bounding boxes (engine/src/collision/geometry.cpp).
//
// Tolerances: meff::Real is float (relative rounding 6e-8 per operation). The mass routines do a
// few dozen operations per triangle on coordinates of order 1..3 m, and the parallel-axis shift
// subtracts terms of order |c|^2, so results carry relative errors of ~1e-6 at most; kRel = 1e-5
// leaves a margin while any formula error (a wrong factor or term) is O(1) relative. Positions
// of order 1..3 m carry absolute errors of a few ulps (~1e-6 m); kAbs = 1e-5 m, far below the
// 0.0025 m weld tolerance and the 0.01 m skin.
#include "error_checks.h"
#include "meff/collision.h"
#include "meff/error.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace meff;

namespace
{

constexpr double kRel = 1e-5;
constexpr double kAbs = 1e-5;

bool IsCounterClockwiseConvex(const Polygon& p)
{
    for (int i = 0; i < p.count; ++i)
    {
        const Vec2 a = p.vertices[i];
        const Vec2 b = p.vertices[(i + 1) % p.count];
        const Vec2 c = p.vertices[(i + 2) % p.count];
        if (!(Cross(b - a, c - b) > 0))
        {
            return false;
        }
    }
    return true;
}

/// Every normal is unit length and every vertex lies behind every face.
void CheckNormals(const Polygon& p)
{
    for (int i = 0; i < p.count; ++i)
    {
        CHECK(p.normals[i].Length() == Approx(1).margin(kAbs));
        const Vec2 edge = p.vertices[(i + 1) % p.count] - p.vertices[i];
        CHECK(Dot(edge, p.normals[i]) == Approx(0).margin(kAbs));
        for (int j = 0; j < p.count; ++j)
        {
            CHECK(Dot(p.normals[i], p.vertices[j] - p.vertices[i]) <= Real(kAbs));
        }
    }
}

bool SamePolygon(const Polygon& a, const Polygon& b)
{
    if (a.count != b.count || a.centroid != b.centroid)
    {
        return false;
    }
    for (int i = 0; i < a.count; ++i)
    {
        if (a.vertices[i] != b.vertices[i] || a.normals[i] != b.normals[i])
        {
            return false;
        }
    }
    return true;
}

} // namespace

TEST_CASE("MakePolygon takes the hull of points given in any order", "[geometry]")
{
    std::array<Vec2, 4> square = {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)};
    std::sort(square.begin(), square.end(),
              [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    int permutations = 0;
    do
    {
        const Polygon p = MakePolygon(square);
        // Box2D's hull starts at the right-most point (the lowest of a tie) and runs
        // counter-clockwise; every permutation must give exactly this.
        REQUIRE(p.count == 4);
        CHECK(p.vertices[0] == Vec2(1, -1));
        CHECK(p.vertices[1] == Vec2(1, 1));
        CHECK(p.vertices[2] == Vec2(-1, 1));
        CHECK(p.vertices[3] == Vec2(-1, -1));
        CHECK(p.normals[0] == Vec2(1, 0));
        CHECK(p.normals[1] == Vec2(0, 1));
        CHECK(p.normals[2] == Vec2(-1, 0));
        CHECK(p.normals[3] == Vec2(0, -1));
        CHECK(p.centroid.x == Approx(0).margin(kAbs));
        CHECK(p.centroid.y == Approx(0).margin(kAbs));
        CHECK(p.radius == 0); // the world sets the skin
        ++permutations;
    } while (std::next_permutation(square.begin(), square.end(),
                                   [](Vec2 a, Vec2 b)
                                   { return a.x < b.x || (a.x == b.x && a.y < b.y); }));
    CHECK(permutations == 24);
}

TEST_CASE("MakePolygon drops interior points and points in the middle of an edge", "[geometry]")
{
    const std::vector<Vec2> points = {Vec2(0, 0), Vec2(2, 0), Vec2(0.5f, 0.5f), Vec2(1, 0),
                                      Vec2(2, 2), Vec2(0, 2), Vec2(1, 2),       Vec2(0, 1)};
    const Polygon p = MakePolygon(points);
    REQUIRE(p.count == 4);
    CHECK(IsCounterClockwiseConvex(p));
    CheckNormals(p);
    CHECK(p.vertices[0] == Vec2(2, 0));
    CHECK(p.centroid.x == Approx(1).epsilon(kRel));
    CHECK(p.centroid.y == Approx(1).epsilon(kRel));
}

TEST_CASE("MakePolygon's hull does not depend on the order of the points", "[geometry]")
{
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> coord(-3, 3);
    int sets = 0;
    while (sets < 200)
    {
        std::vector<Vec2> points(3 + rng() % 6);
        for (Vec2& v : points)
        {
            v = Vec2(coord(rng), coord(rng));
        }
        // Keep points well apart so that welding, which does depend on order, plays no part.
        bool apart = true;
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            for (std::size_t j = 0; j < i; ++j)
            {
                apart = apart && DistanceSquared(points[i], points[j]) > Real(0.01);
            }
        }
        Polygon reference;
        if (meff::test::ErrorMessageOf([&] { reference = MakePolygon(points); }) != "accepted")
        {
            continue; // a sliver hull; rejection is tested elsewhere
        }
        if (!apart)
        {
            continue;
        }
        ++sets;
        CHECK(IsCounterClockwiseConvex(reference));
        CheckNormals(reference);
        // Every input point lies inside (or on) the hull.
        for (Vec2 v : points)
        {
            for (int i = 0; i < reference.count; ++i)
            {
                CHECK(Dot(reference.normals[i], v - reference.vertices[i]) <= Real(kAbs));
            }
        }
        for (int shuffle = 0; shuffle < 5; ++shuffle)
        {
            std::shuffle(points.begin(), points.end(), rng);
            CHECK(SamePolygon(MakePolygon(points), reference));
        }
    }
}

TEST_CASE("MakePolygon welds points closer than kPolygonWeldTolerance", "[geometry]")
{
    SECTION("an exact duplicate is dropped")
    {
        const std::vector<Vec2> points = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 1)};
        const Polygon p = MakePolygon(points);
        CHECK(p.count == 3);
    }
    SECTION("a near duplicate is dropped and the first point of the cluster survives")
    {
        const Vec2 nearOrigin(Real(0.001), Real(0.0015)); // 0.0018 m from the origin
        const std::vector<Vec2> points = {Vec2(0, 0), Vec2(1, 0), nearOrigin, Vec2(0, 1)};
        const Polygon p = MakePolygon(points);
        REQUIRE(p.count == 3);
        const auto found = [&](Vec2 v)
        { return std::find(p.vertices, p.vertices + p.count, v) != p.vertices + p.count; };
        CHECK(found(Vec2(0, 0)));
        CHECK_FALSE(found(nearOrigin));
    }
    SECTION("the tolerance decides between welding and keeping two hull points")
    {
        // Two corners d apart on the bottom edge of a unit square's outline.
        const auto countFor = [](Real d)
        {
            const std::vector<Vec2> points = {Vec2(0, 0), Vec2(d, 0), Vec2(1, 1), Vec2(0, 1)};
            return MakePolygon(points).count;
        };
        CHECK(countFor(Real(0.003)) == 4);
        CHECK(countFor(Real(0.002)) == 3);
    }
}

TEST_CASE("MakePolygon rejects unusable input", "[geometry]")
{
    using Catch::Contains;
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real inf = std::numeric_limits<Real>::infinity();

    SECTION("too few or too many points")
    {
        const std::vector<Vec2> two = {Vec2(0, 0), Vec2(1, 0)};
        MEFF_CHECK_ERROR(MakePolygon(two));
        MEFF_CHECK_ERROR_WITH(MakePolygon(two), Contains("got 2"));
        MEFF_CHECK_ERROR(MakePolygon(std::span<const Vec2>()));
        std::vector<Vec2> nine;
        for (int i = 0; i < 9; ++i)
        {
            const Real angle = Real(2) * kPi * Real(i) / Real(9);
            nine.emplace_back(std::cos(angle), std::sin(angle));
        }
        MEFF_CHECK_ERROR(MakePolygon(nine));
        nine.pop_back();
        CHECK(MakePolygon(nine).count == 8);
    }
    SECTION("non-finite coordinates")
    {
        const std::vector<Vec2> withNan = {Vec2(0, 0), Vec2(1, nan), Vec2(0, 1)};
        MEFF_CHECK_ERROR(MakePolygon(withNan));
        MEFF_CHECK_ERROR_WITH(MakePolygon(withNan), Contains("non-finite"));
        const std::vector<Vec2> withInf = {Vec2(0, 0), Vec2(1, 0), Vec2(-inf, 1)};
        MEFF_CHECK_ERROR(MakePolygon(withInf));
    }
    SECTION("collinear points")
    {
        const std::vector<Vec2> three = {Vec2(0, 0), Vec2(1, 1), Vec2(2, 2)};
        MEFF_CHECK_ERROR(MakePolygon(three));
        MEFF_CHECK_ERROR_WITH(MakePolygon(three), Contains("collinear"));
        const std::vector<Vec2> five = {Vec2(3, 0), Vec2(-1, 0), Vec2(0, 0), Vec2(2, 0),
                                        Vec2(1, 0)};
        MEFF_CHECK_ERROR(MakePolygon(five));
    }
    SECTION("nearly collinear points leave a sliver of (near) zero area")
    {
        // Area 5e-17 m^2, below the epsilon of float and of double (Box2D asserts
        // area > b2_epsilon); the points are not exactly collinear, so the hull has 3 vertices.
        const std::vector<Vec2> sliver = {Vec2(0, 0), Vec2(1, 0), Vec2(Real(0.5), Real(1e-16))};
        MEFF_CHECK_ERROR(MakePolygon(sliver));
        MEFF_CHECK_ERROR_WITH(MakePolygon(sliver), Catch::Contains("area"));
    }
    SECTION("points that weld into fewer than three")
    {
        const std::vector<Vec2> same = {Vec2(1, 1), Vec2(1, 1), Vec2(1, 1)};
        MEFF_CHECK_ERROR(MakePolygon(same));
        MEFF_CHECK_ERROR_WITH(MakePolygon(same), Contains("welding"));
        const std::vector<Vec2> twoClusters = {Vec2(0, 0), Vec2(Real(0.001), 0), Vec2(1, 0),
                                               Vec2(1, Real(0.002))};
        MEFF_CHECK_ERROR(MakePolygon(twoClusters));
    }
}

TEST_CASE("MakePolygon centroid of a triangle is the mean of its vertices", "[geometry]")
{
    const std::vector<Vec2> points = {Vec2(3, 1), Vec2(-1, 2), Vec2(Real(0.5), -2)};
    const Polygon p = MakePolygon(points);
    REQUIRE(p.count == 3);
    CHECK(p.centroid.x == Approx((3.0 - 1.0 + 0.5) / 3.0).margin(kAbs));
    CHECK(p.centroid.y == Approx((1.0 + 2.0 - 2.0) / 3.0).margin(kAbs));
}

TEST_CASE("MakeBox matches b2PolygonShape::SetAsBox", "[geometry]")
{
    const Polygon box = MakeBox(Real(1.5), Real(0.25));
    REQUIRE(box.count == 4);
    CHECK(box.vertices[0] == Vec2(Real(-1.5), Real(-0.25)));
    CHECK(box.vertices[1] == Vec2(Real(1.5), Real(-0.25)));
    CHECK(box.vertices[2] == Vec2(Real(1.5), Real(0.25)));
    CHECK(box.vertices[3] == Vec2(Real(-1.5), Real(0.25)));
    CHECK(box.normals[0] == Vec2(0, -1));
    CHECK(box.normals[1] == Vec2(1, 0));
    CHECK(box.normals[2] == Vec2(0, 1));
    CHECK(box.normals[3] == Vec2(-1, 0));
    CHECK(box.centroid == Vec2(0, 0));
    CHECK(box.radius == 0);
}

TEST_CASE("MakeOffsetBox turns and moves the box", "[geometry]")
{
    const Vec2 center(2, -1);
    const Real angle = kPi / Real(6);
    const Polygon box = MakeOffsetBox(1, Real(0.5), center, angle);
    REQUIRE(box.count == 4);
    CHECK(box.centroid == center);
    const Real c = std::cos(angle), s = std::sin(angle);
    const Vec2 local[4] = {Vec2(-1, Real(-0.5)), Vec2(1, Real(-0.5)), Vec2(1, Real(0.5)),
                           Vec2(-1, Real(0.5))};
    const Vec2 normals[4] = {Vec2(0, -1), Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0)};
    for (int i = 0; i < 4; ++i)
    {
        CHECK(box.vertices[i].x == Approx(c * local[i].x - s * local[i].y + center.x).margin(kAbs));
        CHECK(box.vertices[i].y == Approx(s * local[i].x + c * local[i].y + center.y).margin(kAbs));
        CHECK(box.normals[i].x == Approx(c * normals[i].x - s * normals[i].y).margin(kAbs));
        CHECK(box.normals[i].y == Approx(s * normals[i].x + c * normals[i].y).margin(kAbs));
    }
    CHECK(IsCounterClockwiseConvex(box));
    CheckNormals(box);

    // With no turn the offset is exact.
    const Polygon shifted = MakeOffsetBox(1, 2, Vec2(3, 4), 0);
    CHECK(shifted.vertices[0] == Vec2(2, 2));
    CHECK(shifted.vertices[2] == Vec2(4, 6));
    CHECK(shifted.normals[1] == Vec2(1, 0));
}

TEST_CASE("MakeBox and MakeOffsetBox reject bad extents, centres and angles", "[geometry]")
{
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real inf = std::numeric_limits<Real>::infinity();
    MEFF_CHECK_ERROR(MakeBox(0, 1));
    MEFF_CHECK_ERROR(MakeBox(1, -1));
    MEFF_CHECK_ERROR(MakeBox(nan, 1));
    MEFF_CHECK_ERROR(MakeBox(1, inf));
    MEFF_CHECK_ERROR_WITH(MakeBox(0, 1), Catch::Contains("half-extents"));
    MEFF_CHECK_ERROR(MakeOffsetBox(-1, 1, Vec2(0, 0), 0));
    MEFF_CHECK_ERROR(MakeOffsetBox(1, 1, Vec2(nan, 0), 0));
    MEFF_CHECK_ERROR(MakeOffsetBox(1, 1, Vec2(0, inf), 0));
    MEFF_CHECK_ERROR(MakeOffsetBox(1, 1, Vec2(0, 0), inf));
    MEFF_CHECK_ERROR(MakeOffsetBox(1, 1, Vec2(0, 0), nan));
    MEFF_CHECK_NO_ERROR(MakeBox(Real(1e-3), Real(1e3)));
}

TEST_CASE("Box mass, centre and inertia match the closed forms", "[geometry][mass]")
{
    struct Case
    {
        Real hx, hy;
        Vec2 center;
        Real angle;
        Real density;
    };
    const Case cases[] = {
        {Real(0.5), Real(0.5), Vec2(0, 0), 0, 1},
        {2, Real(0.25), Vec2(0, 0), 0, Real(3.5)},
        {1, Real(0.5), Vec2(3, -2), 0, 2},
        {Real(0.75), Real(1.25), Vec2(Real(-1.5), Real(0.5)), Real(0.7), Real(0.4)},
    };
    for (const Case& k : cases)
    {
        const Polygon box = k.center == Vec2(0, 0) && k.angle == 0
                                ? MakeBox(k.hx, k.hy)
                                : MakeOffsetBox(k.hx, k.hy, k.center, k.angle);
        const MassData md = ComputeMass(box, k.density);
        const double w = 2.0 * k.hx, h = 2.0 * k.hy;
        const double m = 4.0 * k.hx * k.hy * k.density;
        const double c2 = double(k.center.x) * k.center.x + double(k.center.y) * k.center.y;
        CHECK(md.mass == Approx(m).epsilon(kRel));
        CHECK(md.center.x == Approx(k.center.x).margin(kAbs));
        CHECK(md.center.y == Approx(k.center.y).margin(kAbs));
        // Rotation does not change a box's polar moment about its own centre.
        CHECK(md.rotationalInertia == Approx(m * (w * w + h * h) / 12.0 + m * c2).epsilon(kRel));
    }
}

TEST_CASE("Triangle mass and inertia about the body origin", "[geometry][mass]")
{
    // Right triangle with legs a, b along the axes from the origin: area ab/2, centroid
    // (a/3, b/3), polar moment about the right-angle corner m(a^2 + b^2)/6.
    const Real a = 3, b = 2, density = Real(1.5);
    const std::vector<Vec2> points = {Vec2(0, 0), Vec2(a, 0), Vec2(0, b)};
    const MassData md = ComputeMass(MakePolygon(points), density);
    const double m = 0.5 * a * b * density;
    CHECK(md.mass == Approx(m).epsilon(kRel));
    CHECK(md.center.x == Approx(a / 3.0).margin(kAbs));
    CHECK(md.center.y == Approx(b / 3.0).margin(kAbs));
    CHECK(md.rotationalInertia == Approx(m * (a * a + b * b) / 6.0).epsilon(kRel));
}

TEST_CASE("Polygon mass with zero density and invalid arguments", "[geometry][mass]")
{
    const Polygon box = MakeOffsetBox(1, 1, Vec2(2, 0), 0);
    const MassData md = ComputeMass(box, 0);
    CHECK(md.mass == 0);
    CHECK(md.rotationalInertia == 0);
    CHECK(md.center.x == Approx(2).margin(kAbs));
    MEFF_CHECK_ERROR(ComputeMass(box, -1));
    MEFF_CHECK_ERROR(ComputeMass(box, std::numeric_limits<Real>::quiet_NaN()));
    MEFF_CHECK_ERROR(ComputeMass(Polygon{}, 1));
}

TEST_CASE("Circle mass", "[geometry][mass]")
{
    const Circle circle{Vec2(1, -2), Real(0.5)};
    const MassData md = ComputeMass(circle, 2);
    const double m = 2.0 * 3.14159265358979 * 0.25;
    CHECK(md.mass == Approx(m).epsilon(kRel));
    CHECK(md.center == circle.center);
    CHECK(md.rotationalInertia == Approx(m * (0.5 * 0.25 + 5.0)).epsilon(kRel));

    const MassData centred = ComputeMass(Circle{Vec2(0, 0), 2}, 1);
    CHECK(centred.rotationalInertia == Approx(centred.mass * 2.0).epsilon(kRel));
    MEFF_CHECK_ERROR(ComputeMass(circle, -Real(0.1)));
}

TEST_CASE("AABBs of circles, segments and polygons", "[geometry][aabb]")
{
    Transform xf;
    xf.Set(Vec2(1, 2), kPi / Real(2)); // quarter turn: local (x, y) -> (-y, x)

    SECTION("circle")
    {
        const AABB box = ComputeAABB(Circle{Vec2(1, 0), Real(0.5)}, xf);
        CHECK(box.lowerBound.x == Approx(0.5).margin(kAbs));
        CHECK(box.lowerBound.y == Approx(2.5).margin(kAbs));
        CHECK(box.upperBound.x == Approx(1.5).margin(kAbs));
        CHECK(box.upperBound.y == Approx(3.5).margin(kAbs));
    }
    SECTION("segment includes its skin")
    {
        const Segment segment{Vec2(-1, 0), Vec2(2, 1), Real(0.01)};
        const AABB box = ComputeAABB(segment, xf);
        // World ends (1, 1) and (0, 4).
        CHECK(box.lowerBound.x == Approx(-0.01).margin(kAbs));
        CHECK(box.lowerBound.y == Approx(0.99).margin(kAbs));
        CHECK(box.upperBound.x == Approx(1.01).margin(kAbs));
        CHECK(box.upperBound.y == Approx(4.01).margin(kAbs));
    }
    SECTION("polygon includes its skin")
    {
        Polygon box = MakeBox(2, Real(0.5));
        box.radius = Real(0.01);
        const AABB aabb = ComputeAABB(box, xf);
        CHECK(aabb.lowerBound.x == Approx(1 - 0.5 - 0.01).margin(kAbs));
        CHECK(aabb.lowerBound.y == Approx(2 - 2 - 0.01).margin(kAbs));
        CHECK(aabb.upperBound.x == Approx(1 + 0.5 + 0.01).margin(kAbs));
        CHECK(aabb.upperBound.y == Approx(2 + 2 + 0.01).margin(kAbs));

        Transform turned;
        turned.Set(Vec2(0, 0), kPi / Real(4));
        const AABB diamond = ComputeAABB(MakeBox(1, 1), turned);
        CHECK(diamond.upperBound.x == Approx(std::sqrt(2.0)).margin(kAbs));
        CHECK(diamond.lowerBound.y == Approx(-std::sqrt(2.0)).margin(kAbs));
        CHECK(diamond.IsValid());
    }
}
