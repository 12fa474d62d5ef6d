// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace meff::cli
{

Progress::Progress(std::string label, long long total, std::string unit)
    : m_label(std::move(label)), m_total(total), m_unit(std::move(unit)),
      m_enabled(::isatty(STDERR_FILENO) == 1), m_start(std::chrono::steady_clock::now())
{
}

Progress::~Progress()
{
    Finish();
}

void Progress::Update(long long done)
{
    if (!m_enabled)
    {
        return;
    }
    constexpr int kWidth = 30;
    const int filled = m_total > 0 ? int(done * kWidth / m_total) : kWidth;
    std::string bar(std::size_t(filled), '#');
    bar.resize(kWidth, '.');
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    std::string timing = FormatDuration(elapsed) + " elapsed";
    if (done > 0 && done < m_total)
    {
        timing += ", ~" + FormatDuration(elapsed / double(done) * double(m_total - done)) + " left";
    }
    // \033[K erases what a longer earlier line left to the right.
    std::fprintf(stderr, "\r%s [%s] %lld/%lld %s, %s\033[K", m_label.c_str(), bar.c_str(), done,
                 m_total, m_unit.c_str(), timing.c_str());
    std::fflush(stderr);
    m_shown = true;
}

void Progress::Clear()
{
    if (m_shown)
    {
        std::fputs("\r\033[K", stderr);
        std::fflush(stderr);
        m_shown = false;
    }
}

void Progress::Finish()
{
    if (m_shown)
    {
        std::fputc('\n', stderr);
        m_shown = false;
    }
}

std::string FormatDuration(double seconds)
{
    const long long total = std::llround(std::max(seconds, 0.0));
    char text[32];
    if (total >= 3600)
    {
        std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", total / 3600, total / 60 % 60,
                      total % 60);
    }
    else
    {
        std::snprintf(text, sizeof text, "%lld:%02lld", total / 60, total % 60);
    }
    return text;
}

} // namespace meff::cli
