// Groups of kLanes constraints, colour after colour, and how a colour's groups are spread over the
// world's threads: shared by the contact lanes (contact_lanes.h) and the joint lanes
// (revolute_lanes.h). A colour's groups share no moving body, so they may be solved at the same
// time; each writes its own bodies, its own rows and its worker's discard slot
// (ScatterFromWorker), so the results are the same bit for bit for any thread count.
#pragma once

#include "dynamics/solver_types.h"
#include "solvers/colour/graph_colouring.h"
#include "solvers/lanes/lane_bodies.h"
#include "tasks/parallel_ranges.h"

#include <cstdint>
#include <vector>

namespace meff::detail
{

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
/// least `minGroups` to a thread, on the world's threads (data.tasks).
template <typename Solve>
void ForEachGroupOfColour(const std::vector<std::int32_t>& starts, int c, const SolverData& data,
                          int minGroups, Solve&& solve)
{
    const std::int32_t first = starts[c];
    ForRanges(data.tasks, starts[c + 1] - first, minGroups,
              [&](int begin, int end, int worker)
              {
                  const DiscardSlots discard{data.discardIndex, data.discardIndex + worker};
                  for (std::int32_t i = first + begin; i < first + end; ++i)
                  {
                      solve(i, discard);
                  }
              });
}

} // namespace meff::detail
