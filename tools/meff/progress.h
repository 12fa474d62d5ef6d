// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Progress of a long run on a terminal: one line on stderr, redrawn in place, with the work
// done, the time elapsed and an estimate of the time left. Silent when stderr is not a
// terminal, so logs and CI output never fill with carriage-return lines.
#pragma once

#include <chrono>
#include <string>

namespace meff::cli
{

class Progress
{
  public:
    /// `unit` names what is counted ("scenes", "frames", "settings"). 64-bit: a render may
    /// count 2^31 frames.
    Progress(std::string label, long long total, std::string unit);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// Redraws the line with `done` of the total finished.
    void Update(long long done);
    /// Erases the line, so that the caller can print a line of its own; the next Update
    /// draws it again.
    void Clear();
    /// Ends the line for good (called by the destructor too).
    void Finish();

    bool Enabled() const { return m_enabled; }

  private:
    std::string m_label;
    long long m_total = 0;
    std::string m_unit;
    bool m_enabled = false;
    bool m_shown = false;
    std::chrono::steady_clock::time_point m_start;
};

/// "1:05" for 65 s, "1:02:03" past an hour.
std::string FormatDuration(double seconds);

} // namespace meff::cli
