// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A small deterministic random generator for tests: the same sequence on every platform and
// standard library (std:: distributions are not specified bit for bit).
#pragma once

#include <cstdint>

namespace meff::test
{

class Random
{
  public:
    explicit Random(std::uint64_t seed)
        : m_state(seed * 6364136223846793005ull + 1442695040888963407ull)
    {
    }

    std::uint32_t Next()
    {
        m_state ^= m_state << 13;
        m_state ^= m_state >> 7;
        m_state ^= m_state << 17;
        return static_cast<std::uint32_t>(m_state >> 32);
    }
    float Uniform(float lo, float hi)
    {
        const double unit = static_cast<double>(Next()) / 4294967296.0;
        return lo + static_cast<float>(unit) * (hi - lo);
    }
    int Index(int n) { return static_cast<int>(Next() % static_cast<std::uint32_t>(n)); }

  private:
    std::uint64_t m_state;
};

} // namespace meff::test
