// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "model/shape_proxy.h"

#include "model/shape.h"

namespace meff::detail
{

DistanceProxy MakeProxy(const Shape& shape)
{
    switch (shape.type)
    {
    case ShapeType::Circle:
        return meff::MakeProxy(shape.circle);
    case ShapeType::Polygon:
    case ShapeType::Capsule:
        return meff::MakeProxy(shape.polygon);
    case ShapeType::Segment:
        return meff::MakeProxy(shape.segment);
    case ShapeType::ChainSegment:
        return meff::MakeProxy(shape.chainSegment);
    }
    return {};
}

} // namespace meff::detail
