// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Exact answers to compare a solver with, in double: one copy that `meff sweep`
// (tools/meff/sweep_command.cpp: its pendulum and cradle error models) and the tests
// (tests/extreme/soft_step_measures.h) both use. Needs only the standard library.
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

} // namespace meff::analytic
