// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/lanes/wide_real.h"

namespace meff::detail
{

namespace
{
constexpr RealW InEveryLane(Real x)
{
    return RealW{} + x;
}
} // namespace

// The values SinCosW's comment derives (wide_real.h), each the Real nearest to the literal.
constinit const SinCosConstantsW kSinCosW{
    InEveryLane(Real(6000)),
    InEveryLane(-Real(6000)),
    InEveryLane(Real(0.636619772367581343)),
    InEveryLane(Real(12582912.0)),
    InEveryLane(Real(1.5703125)),              // 201/128
    InEveryLane(Real(4.838705062866211e-4)),   // 12 significant bits
    InEveryLane(Real(-4.371138828673793e-08)), // π/2 − C1 − C2
    InEveryLane(Real(-0.16666655242443085)),
    InEveryLane(Real(0.008332165889441967)),
    InEveryLane(Real(-0.00019515953317750245)),
    InEveryLane(Real(-0.5)),
    InEveryLane(Real(0.04166664555668831)),
    InEveryLane(Real(-0.0013887342065572739)),
    InEveryLane(Real(2.4435852537862957e-05)),
    InEveryLane(Real(1)),
};

} // namespace meff::detail
