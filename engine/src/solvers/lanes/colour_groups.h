// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Groups of kLanes constraints, colour after colour, and how a colour's groups are spread over the
// world's threads: shared by the colour back end's contact and joint lanes (contact_lanes.h,
// revolute_lanes.h) and the soft step's (ColourGroups: soft_contact_lanes.h,
// soft_revolute_lanes.h). A colour's groups share no moving body, so they may be solved at the
// same time; each writes its own bodies, its own rows and its worker's discard slot
// (WithWorkerStores), so the results are the same bit for bit for any thread count.
#pragma once

#include "model/solver_types.h"
#include "solvers/lanes/graph_colouring.h"
#include "solvers/lanes/lane_bodies.h"
#include "tasks/parallel_ranges.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace meff::detail
{

/// The fewest groups a thread is handed at once: a range must pay for handing it out (a
/// compare-and-swap, perhaps a thread's wake-up), so a colour of fewer than two ranges stays on
/// the calling thread.
inline constexpr int kMinGroupsPerTask = 64;

/// Cuts each colour of `colouring` into groups of kLanes constraints (the last of a colour may
/// be partly empty): colour c's groups are [starts[c], starts[c + 1]). Returns the group count.
inline std::int32_t GroupStartsOf(const ConstraintColouring& colouring,
                                  std::vector<std::int32_t>& starts)
{
    const int colours = colouring.ColourCount();
    starts.resize(static_cast<std::size_t>(colours) + 1);
    starts[0] = 0;
    for (int c = 0; c < colours; ++c)
    {
        const std::int32_t count = colouring.colourStarts[c + 1] - colouring.colourStarts[c];
        starts[c + 1] = starts[c] + (count + kLanes - 1) / kLanes;
    }
    return starts.back();
}

/// Runs solve(group, discard) on each of colour c's groups ([starts[c], starts[c + 1])), at
/// least `minGroups` to a thread, on `tasks` (null: this thread); `discardIndex` is worker 0's
/// discard slot (SolverData::discardIndex).
template <typename Solve>
void ForEachGroupOfColour(const std::vector<std::int32_t>& starts, int c, TaskSystem* tasks,
                          std::int32_t discardIndex, int minGroups, Solve&& solve)
{
    const std::int32_t first = starts[c];
    ForRanges(tasks, starts[c + 1] - first, minGroups,
              [&](int begin, int end, int worker)
              {
                  const DiscardSlots discard{discardIndex, discardIndex + worker};
                  for (std::int32_t i = first + begin; i < first + end; ++i)
                  {
                      solve(i, discard);
                  }
              });
}

/// Runs f(group, colour) on every group of every colour ([0, starts.back())), at least
/// `minGroups` to a range, on `tasks` (null: this thread): for what each group does alone
/// (preparing its rows, copying out its impulses), which needs no colour order.
template <typename F>
void ForEachGroupWithColour(const std::vector<std::int32_t>& starts, TaskSystem* tasks,
                            int minGroups, F&& f)
{
    ForRanges(tasks, starts.back(), minGroups,
              [&](int begin, int end, int)
              {
                  auto colour = static_cast<int>(
                      std::upper_bound(starts.begin(), starts.end(), begin) - starts.begin() - 1);
                  for (std::int32_t i = begin; i < end; ++i)
                  {
                      while (i >= starts[colour + 1])
                      {
                          ++colour;
                      }
                      f(i, colour);
                  }
              });
}

/// A group's constraints: positions [first, end) of colouring.order (at most kLanes).
struct GroupRows
{
    std::int32_t first, end;
};

/// The constraints of group i of colour `colour`, whose groups start at starts[colour].
inline GroupRows GroupRowsOf(const std::vector<std::int32_t>& starts,
                             const ConstraintColouring& colouring, std::int32_t i, int colour)
{
    const std::int32_t first = colouring.colourStarts[colour] + (i - starts[colour]) * kLanes;
    return {first, std::min(first + kLanes, colouring.colourStarts[colour + 1])};
}

/// The same on the world's threads of `data` (data.tasks, data.discardIndex).
template <typename Solve>
void ForEachGroupOfColour(const std::vector<std::int32_t>& starts, int c, const SolverData& data,
                          int minGroups, Solve&& solve)
{
    ForEachGroupOfColour(starts, c, data.tasks, data.discardIndex, minGroups, solve);
}

/// A colouring's groups and the threads they run on, for a solver whose passes all take the
/// same threads (the soft step's lanes): colour c's groups are [starts[c], starts[c + 1]).
struct ColourGroups
{
    std::vector<std::int32_t> starts{0};
    TaskSystem* tasks = nullptr;   ///< the world's threads, or null
    std::int32_t discardIndex = 0; ///< worker 0's discard slot (SolverData::discardIndex)

    /// Cuts `colouring` into groups (GroupStartsOf) for `threads`, whose worker 0 writes the
    /// discard slot `discard`; returns the group count.
    std::int32_t Cut(const ConstraintColouring& colouring, TaskSystem* threads,
                     std::int32_t discard)
    {
        tasks = threads;
        discardIndex = discard;
        return GroupStartsOf(colouring, starts);
    }
    int ColourCount() const { return static_cast<int>(starts.size()) - 1; }
    /// The colour of group i.
    int ColourOf(std::int32_t i) const
    {
        return static_cast<int>(std::upper_bound(starts.begin(), starts.end(), i) -
                                starts.begin()) -
               1;
    }
    using Rows = GroupRows;
    /// Group i's constraints (GroupRowsOf).
    Rows RowsOf(std::int32_t i, const ConstraintColouring& colouring) const
    {
        return GroupRowsOf(starts, colouring, i, ColourOf(i));
    }
    /// Runs f(group) on every group, in ranges on the threads: for what each group does alone
    /// (packing, scaling or copying its own rows).
    template <typename F>
    void ForEachGroup(F&& f) const
    {
        ForEachIndex(tasks, starts.back(), kMinGroupsPerTask, f);
    }
    /// Runs f(group, discard) colour after colour, a colour's groups on the threads: for the
    /// sweeps, whose groups of one colour share no moving body.
    template <typename F>
    void ForEachGroupByColour(F&& f) const
    {
        for (int c = 0; c < ColourCount(); ++c)
        {
            ForEachGroupOfColour(starts, c, tasks, discardIndex, kMinGroupsPerTask, f);
        }
    }
};

} // namespace meff::detail
