// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Vectors, rotations and transforms in 2D.
//
// The operation order of every function here matches Box2D 2.4.1's b2_math.h, because
// meff is validated against Box2D to float precision: a*b+c and c+a*b round differently.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace meff
{

#ifdef MEFF_DOUBLE
using Real = double;
#else
/// The engine's scalar. float by default, as Box2D 2.4.1, so that the two engines can agree
/// frame by frame; build with -DMEFF_DOUBLE=ON for double (see docs/api-guide.md, "Scalar type").
using Real = float;
#endif

inline constexpr Real kEpsilon = std::numeric_limits<Real>::epsilon();
inline constexpr Real kMaxReal = std::numeric_limits<Real>::max();
inline constexpr Real kPi = Real(3.14159265359);

inline bool IsValid(Real x)
{
    return std::isfinite(x);
}

/// A 2D vector: a point or a direction (m, m/s, N, ... as the use says).
struct Vec2
{
    Real x = 0; ///< first component
    Real y = 0; ///< second component

    constexpr Vec2() = default;
    /// The vector (x_, y_).
    constexpr Vec2(Real x_, Real y_) : x(x_), y(y_) {}

    /// The opposite vector.
    Vec2 operator-() const { return {-x, -y}; }
    /// Adds v.
    Vec2& operator+=(Vec2 v)
    {
        x += v.x;
        y += v.y;
        return *this;
    }
    /// Subtracts v.
    Vec2& operator-=(Vec2 v)
    {
        x -= v.x;
        y -= v.y;
        return *this;
    }
    /// Scales by s.
    Vec2& operator*=(Real s)
    {
        x *= s;
        y *= s;
        return *this;
    }
    /// x for i = 0, y otherwise.
    Real operator[](int i) const { return i == 0 ? x : y; }

    /// Euclidean length.
    Real Length() const { return std::sqrt(x * x + y * y); }
    /// Squared length (no square root).
    Real LengthSquared() const { return x * x + y * y; }
    /// Normalizes in place and returns the old length; leaves a near-zero vector unchanged and
    /// returns 0.
    Real Normalize()
    {
        const Real length = Length();
        if (length < kEpsilon)
        {
            return 0;
        }
        const Real invLength = Real(1) / length;
        x *= invLength;
        y *= invLength;
        return length;
    }
    /// The vector turned a quarter turn counter-clockwise: (-y, x).
    Vec2 Skew() const { return {-y, x}; }
    /// Both components finite.
    bool IsValid() const { return meff::IsValid(x) && meff::IsValid(y); }
};

inline Vec2 operator+(Vec2 a, Vec2 b)
{
    return {a.x + b.x, a.y + b.y};
}
inline Vec2 operator-(Vec2 a, Vec2 b)
{
    return {a.x - b.x, a.y - b.y};
}
inline Vec2 operator*(Real s, Vec2 a)
{
    return {s * a.x, s * a.y};
}
inline bool operator==(Vec2 a, Vec2 b)
{
    return a.x == b.x && a.y == b.y;
}
inline bool operator!=(Vec2 a, Vec2 b)
{
    return !(a == b);
}

inline Real Dot(Vec2 a, Vec2 b)
{
    return a.x * b.x + a.y * b.y;
}
/// 2D cross product a × b (the z component of the 3D one).
inline Real Cross(Vec2 a, Vec2 b)
{
    return a.x * b.y - a.y * b.x;
}
/// v × s: the vector v crossed with the out-of-plane scalar s.
inline Vec2 Cross(Vec2 a, Real s)
{
    return {s * a.y, -s * a.x};
}
/// s × v: the out-of-plane scalar s crossed with v (angular velocity × lever arm).
inline Vec2 Cross(Real s, Vec2 a)
{
    return {-s * a.y, s * a.x};
}
inline Real Distance(Vec2 a, Vec2 b)
{
    return (a - b).Length();
}
inline Real DistanceSquared(Vec2 a, Vec2 b)
{
    const Vec2 c = a - b;
    return Dot(c, c);
}
inline Vec2 Abs(Vec2 a)
{
    return {std::abs(a.x), std::abs(a.y)};
}
// Min and Max pick the same operand as Box2D's b2Min/b2Max on ties (a < b ? a : b), which
// differs from std::min for −0 and +0.
inline Real Min(Real a, Real b)
{
    return a < b ? a : b;
}
inline Real Max(Real a, Real b)
{
    return a > b ? a : b;
}
inline Vec2 Min(Vec2 a, Vec2 b)
{
    return {Min(a.x, b.x), Min(a.y, b.y)};
}
inline Vec2 Max(Vec2 a, Vec2 b)
{
    return {Max(a.x, b.x), Max(a.y, b.y)};
}
/// Clamps a to [low, high], with Box2D's b2Clamp tie rule: Max(low, Min(a, high)).
inline Real Clamp(Real a, Real low, Real high)
{
    return Max(low, Min(a, high));
}

/// A 2×2 matrix stored by columns.
struct Mat22
{
    Vec2 ex{1, 0}; ///< first column
    Vec2 ey{0, 1}; ///< second column

    /// The inverse; the zero matrix when this one is singular (as Box2D's b2Mat22).
    Mat22 GetInverse() const
    {
        const Real a = ex.x, b = ey.x, c = ex.y, d = ey.y;
        Real det = a * d - b * c;
        if (det != 0)
        {
            det = Real(1) / det;
        }
        Mat22 m{};
        m.ex.x = det * d;
        m.ey.x = -det * b;
        m.ex.y = -det * c;
        m.ey.y = det * a;
        return m;
    }
    /// Solves A·x = b by Cramer's rule; returns 0 for a singular matrix's determinant factor.
    Vec2 Solve(Vec2 b) const
    {
        const Real a11 = ex.x, a12 = ey.x, a21 = ex.y, a22 = ey.y;
        Real det = a11 * a22 - a12 * a21;
        if (det != 0)
        {
            det = Real(1) / det;
        }
        return {det * (a22 * b.x - a12 * b.y), det * (a11 * b.y - a21 * b.x)};
    }
};

inline Vec2 Mul(const Mat22& A, Vec2 v)
{
    return {A.ex.x * v.x + A.ey.x * v.y, A.ex.y * v.x + A.ey.y * v.y};
}

/// A rotation stored as its sine and cosine.
struct Rot
{
    Real s = 0; ///< sine of the angle
    Real c = 1; ///< cosine of the angle

    Rot() = default;
    /// The rotation by `angle` (rad, counter-clockwise).
    explicit Rot(Real angle) : s(std::sin(angle)), c(std::cos(angle)) {}
    /// Becomes the rotation by `angle` (rad).
    void Set(Real angle)
    {
        s = std::sin(angle);
        c = std::cos(angle);
    }
    /// The angle in (−π, π] (rad).
    Real GetAngle() const { return std::atan2(s, c); }
    /// The rotated x axis (c, s).
    Vec2 GetXAxis() const { return {c, s}; }
    /// The rotated y axis (−s, c).
    Vec2 GetYAxis() const { return {-s, c}; }
};

/// q·v
inline Vec2 Mul(Rot q, Vec2 v)
{
    return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}
/// qᵀ·v
inline Vec2 MulT(Rot q, Vec2 v)
{
    return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y};
}
/// q·r
inline Rot Mul(Rot q, Rot r)
{
    Rot qr{};
    qr.s = q.s * r.c + q.c * r.s;
    qr.c = q.c * r.c - q.s * r.s;
    return qr;
}
/// qᵀ·r
inline Rot MulT(Rot q, Rot r)
{
    Rot qr{};
    qr.s = q.c * r.s - q.s * r.c;
    qr.c = q.c * r.c + q.s * r.s;
    return qr;
}

/// A rigid transform: rotation q then translation p.
struct Transform
{
    Vec2 p{0, 0}; ///< translation (m)
    Rot q{};      ///< rotation

    Transform() = default;
    /// Rotation `rotation`, then translation `position`.
    Transform(Vec2 position, Rot rotation) : p(position), q(rotation) {}
    /// Becomes the translation `position` (m) and rotation by `angle` (rad).
    void Set(Vec2 position, Real angle)
    {
        p = position;
        q.Set(angle);
    }
};

inline Vec2 Mul(const Transform& T, Vec2 v)
{
    const Real x = (T.q.c * v.x - T.q.s * v.y) + T.p.x;
    const Real y = (T.q.s * v.x + T.q.c * v.y) + T.p.y;
    return {x, y};
}
inline Vec2 MulT(const Transform& T, Vec2 v)
{
    const Real px = v.x - T.p.x;
    const Real py = v.y - T.p.y;
    const Real x = (T.q.c * px + T.q.s * py);
    const Real y = (-T.q.s * px + T.q.c * py);
    return {x, y};
}
/// A·B
inline Transform Mul(const Transform& A, const Transform& B)
{
    return {Mul(A.q, B.p) + A.p, Mul(A.q, B.q)};
}
/// Aᵀ·B
inline Transform MulT(const Transform& A, const Transform& B)
{
    return {MulT(A.q, B.p - A.p), MulT(A.q, B.q)};
}

/// The motion of a body's centre of mass over one step, for continuous collision.
struct Sweep
{
    Vec2 localCenter{}; ///< centre of mass in body coordinates (m)
    Vec2 c0{};          ///< centre of mass in world coordinates at t0 (m)
    Vec2 c{};           ///< centre of mass in world coordinates now (m)
    Real a0 = 0;        ///< angle at t0 (rad)
    Real a = 0;         ///< angle now (rad)
    Real alpha0 = 0;    ///< fraction of the step already advanced, in [0,1)

    /// The body transform at fraction beta of the step.
    Transform GetTransform(Real beta) const
    {
        Transform xf{};
        xf.p = (Real(1) - beta) * c0 + beta * c;
        const Real angle = (Real(1) - beta) * a0 + beta * a;
        xf.q.Set(angle);
        xf.p -= Mul(xf.q, localCenter);
        return xf;
    }

    /// Moves the start of the sweep forward to fraction `alpha` of the step (alpha0 ≤ alpha <
    /// 1): c0 and a0 become the pose at alpha, and the rest of the sweep is unchanged.
    void Advance(Real alpha)
    {
        const Real beta = (alpha - alpha0) / (Real(1) - alpha0);
        c0 += beta * (c - c0);
        a0 += beta * (a - a0);
        alpha0 = alpha;
    }

    /// Shifts both angles by the same whole number of turns so that a0 lies in [0, 2π): large
    /// angles make the time-of-impact root finder lose precision.
    void Normalize()
    {
        const Real twoPi = Real(2) * kPi;
        const Real d = twoPi * std::floor(a0 / twoPi);
        a0 -= d;
        a -= d;
    }
};

/// An axis-aligned bounding box.
struct AABB
{
    Vec2 lowerBound{}; ///< smallest x and y (m)
    Vec2 upperBound{}; ///< largest x and y (m)

    /// The centre (m).
    Vec2 GetCenter() const { return Real(0.5) * (lowerBound + upperBound); }
    /// Half the size along each axis (m).
    Vec2 GetExtents() const { return Real(0.5) * (upperBound - lowerBound); }
    /// Perimeter (m), the broad phase's cost measure.
    Real GetPerimeter() const
    {
        const Real wx = upperBound.x - lowerBound.x;
        const Real wy = upperBound.y - lowerBound.y;
        return Real(2) * (wx + wy);
    }
    /// Whether `aabb` lies inside this box (borders included).
    bool Contains(const AABB& aabb) const
    {
        return lowerBound.x <= aabb.lowerBound.x && lowerBound.y <= aabb.lowerBound.y &&
               aabb.upperBound.x <= upperBound.x && aabb.upperBound.y <= upperBound.y;
    }
    /// Finite bounds, upper not below lower.
    bool IsValid() const
    {
        const Vec2 d = upperBound - lowerBound;
        return d.x >= 0 && d.y >= 0 && lowerBound.IsValid() && upperBound.IsValid();
    }
};

inline AABB Combine(const AABB& a, const AABB& b)
{
    return {Min(a.lowerBound, b.lowerBound), Max(a.upperBound, b.upperBound)};
}
inline bool TestOverlap(const AABB& a, const AABB& b)
{
    const Vec2 d1 = b.lowerBound - a.upperBound;
    const Vec2 d2 = a.lowerBound - b.upperBound;
    if (d1.x > 0 || d1.y > 0)
    {
        return false;
    }
    if (d2.x > 0 || d2.y > 0)
    {
        return false;
    }
    return true;
}

} // namespace meff
