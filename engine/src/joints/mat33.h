// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// 3-vectors and 3×3 matrices for the weld joint's point-and-angle block (Box2D's b2Vec3 and
// b2Mat33). Every operation keeps Box2D 2.4.1's floating-point order, since the joint that
// uses them is checked against Box2D bit for bit.
#pragma once

#include "meff/math.h"

namespace meff::detail
{

struct Vec3
{
    Real x = 0, y = 0, z = 0;

    Vec3() = default;
    Vec3(Real x_, Real y_, Real z_) : x(x_), y(y_), z(z_) {}
    Vec3 operator-() const { return {-x, -y, -z}; }
    Vec3& operator+=(const Vec3& v)
    {
        x += v.x;
        y += v.y;
        z += v.z;
        return *this;
    }
    Vec3& operator*=(Real s)
    {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
};

inline Vec3 operator+(const Vec3& a, const Vec3& b)
{
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator*(Real s, const Vec3& v)
{
    return {s * v.x, s * v.y, s * v.z};
}
inline Real Dot(const Vec3& a, const Vec3& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// A 3×3 matrix stored by columns.
struct Mat33
{
    Vec3 ex, ey, ez;

    /// Solves A·x = b by Cramer's rule (a singular matrix gives x = 0).
    Vec3 Solve33(const Vec3& b) const
    {
        Real det = Dot(ex, Cross(ey, ez));
        if (det != 0)
        {
            det = Real(1) / det;
        }
        return {det * Dot(b, Cross(ey, ez)), det * Dot(ex, Cross(b, ez)),
                det * Dot(ex, Cross(ey, b))};
    }

    /// Solves the upper-left 2×2 block only: A₂₂·x = b.
    Vec2 Solve22(Vec2 b) const
    {
        const Real a11 = ex.x, a12 = ey.x, a21 = ex.y, a22 = ey.y;
        Real det = a11 * a22 - a12 * a21;
        if (det != 0)
        {
            det = Real(1) / det;
        }
        return {det * (a22 * b.x - a12 * b.y), det * (a11 * b.y - a21 * b.x)};
    }

    /// The inverse of the upper-left 2×2 block, padded with zeros (zero if singular).
    Mat33 GetInverse22() const
    {
        const Real a = ex.x, b = ey.x, c = ex.y, d = ey.y;
        Real det = a * d - b * c;
        if (det != 0)
        {
            det = Real(1) / det;
        }
        Mat33 m;
        m.ex = {det * d, -det * c, 0};
        m.ey = {-det * b, det * a, 0};
        m.ez = {0, 0, 0};
        return m;
    }

    /// The inverse of a symmetric matrix (zero if singular); reads only the upper triangle.
    Mat33 GetSymInverse33() const
    {
        Real det = Dot(ex, Cross(ey, ez));
        if (det != 0)
        {
            det = Real(1) / det;
        }
        const Real a11 = ex.x, a12 = ey.x, a13 = ez.x;
        const Real a22 = ey.y, a23 = ez.y;
        const Real a33 = ez.z;
        Mat33 m;
        m.ex.x = det * (a22 * a33 - a23 * a23);
        m.ex.y = det * (a13 * a23 - a12 * a33);
        m.ex.z = det * (a12 * a23 - a13 * a22);
        m.ey.x = m.ex.y;
        m.ey.y = det * (a11 * a33 - a13 * a13);
        m.ey.z = det * (a13 * a12 - a11 * a23);
        m.ez.x = m.ex.z;
        m.ez.y = m.ey.z;
        m.ez.z = det * (a11 * a22 - a12 * a12);
        return m;
    }
};

/// A·v, summed column by column as Box2D's b2Mul(b2Mat33, b2Vec3).
inline Vec3 Mul(const Mat33& A, const Vec3& v)
{
    return v.x * A.ex + v.y * A.ey + v.z * A.ez;
}

/// The upper-left 2×2 block times v (Box2D's b2Mul22).
inline Vec2 Mul22(const Mat33& A, Vec2 v)
{
    return {A.ex.x * v.x + A.ey.x * v.y, A.ex.y * v.x + A.ey.y * v.y};
}

} // namespace meff::detail
