// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Exact answers to compare a solver with, in double: one copy that `meff sweep`
// (tools/meff/sweep_command.cpp: its pendulum, cradle and bounce error models) and the tests
// (tests/extreme/soft_step_measures.h, tests/test_analytic.cpp) use. Needs only the standard
// library.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace meff::analytic
{

/// The motion of a rigid pendulum ψ'' = −k·sin ψ (ψ from hanging straight down along gravity,
/// k = m·g·d/I about the pivot), sampled every `sampleDt` seconds: samples + 1 angles and
/// angular velocities, sample 0 being (psi0, omega0). Integrated by classical fourth-order
/// Runge-Kutta at `substepsPerSample` steps per sample; the error, ~h⁴ per unit time, is far
/// below float round-off in the engines at the steps its users take (≤ 67 µs).
class PendulumMotion
{
  public:
    PendulumMotion(double k, double psi0, double omega0, double sampleDt, int substepsPerSample,
                   int samples)
    {
        const double h = sampleDt / substepsPerSample;
        double psi = psi0;
        double omega = omega0;
        const auto accel = [k](double angle) { return -k * std::sin(angle); };
        m_psi.push_back(psi);
        m_omega.push_back(omega);
        for (int s = 0; s < samples; ++s)
        {
            for (int i = 0; i < substepsPerSample; ++i)
            {
                const double k1p = omega;
                const double k1w = accel(psi);
                const double k2p = omega + 0.5 * h * k1w;
                const double k2w = accel(psi + 0.5 * h * k1p);
                const double k3p = omega + 0.5 * h * k2w;
                const double k3w = accel(psi + 0.5 * h * k2p);
                const double k4p = omega + h * k3w;
                const double k4w = accel(psi + h * k3p);
                psi += h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
                omega += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
            }
            m_psi.push_back(psi);
            m_omega.push_back(omega);
        }
    }

    /// ψ (rad) and ψ' (rad/s) at sample `k` (time k·sampleDt).
    double Angle(std::size_t k) const { return m_psi.at(k); }
    double AngularVelocity(std::size_t k) const { return m_omega.at(k); }

  private:
    std::vector<double> m_psi, m_omega;
};

/// A point or direction in the plane, in double.
struct Vec2d
{
    double x = 0;
    double y = 0;
};

/// Where a body on a rod of length `length` from `pivot` is at angle ψ from `down` (a unit
/// vector), turning counter-clockwise.
inline Vec2d OnRod(Vec2d pivot, Vec2d down, double length, double psi)
{
    const double c = std::cos(psi);
    const double s = std::sin(psi);
    return {pivot.x + length * (c * down.x - s * down.y),
            pivot.y + length * (s * down.x + c * down.y)};
}

/// An ideal Newton's cradle: `count` balls hanging in a row on equal rods with vanishing gaps,
/// the first released at ψ0 from the vertical. The collisions pass the whole momentum along
/// the row within an instant, so the cradle is one pendulum folded at the bottom: while that
/// pendulum's angle ψ (PendulumMotion from ψ0) is on the first ball's side, the first ball
/// swings with it and the others hang; past the bottom the last ball swings out at ψ, and the
/// others hang. The angle of ball `n` (0 the first, count − 1 the last) when the pendulum is
/// at ψ.
inline double CradleBallAngle(std::size_t n, std::size_t count, double psi0, double psi)
{
    const bool firstSwings = psi * psi0 >= 0;
    const bool swings = firstSwings ? n == 0 : n + 1 == count;
    return swings ? psi : 0.0;
}

/// A ball dropped on flat ground under gravity g (> 0, along −y), its centre of mass starting
/// at height y0 with vertical velocity v0 and touching the ground at `contactHeight`: each
/// rebound leaves at e times the arrival speed while that speed is at least `threshold` (the
/// restitution threshold; below it the ball stays down), so it rises to e² times the previous
/// height. The heights of the centre of mass at the tops of the rebounds reached within
/// `seconds`, in order.
inline std::vector<double> BounceApexes(double e, double threshold, double g, double y0, double v0,
                                        double contactHeight, double seconds)
{
    std::vector<double> apexes;
    // First arrival: y0 + v0·t − g·t²/2 = contact height.
    double speed = std::sqrt(v0 * v0 + 2 * g * (y0 - contactHeight));
    double time = (v0 + speed) / g;
    // speed > 0: with no threshold a rebound of zero speed would repeat forever.
    while (speed >= threshold && speed > 0)
    {
        const double up = e * speed;
        const double apexTime = time + up / g;
        if (apexTime > seconds)
        {
            break;
        }
        apexes.push_back(contactHeight + up * up / (2 * g));
        time += 2 * up / g;
        speed = up;
    }
    return apexes;
}

} // namespace meff::analytic
