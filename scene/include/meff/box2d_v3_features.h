// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// What a scene holds that Box2D 2.4.1 has no counterpart for (Box2D v3's shapes, joint
// springs and character mover): `meff validate` cannot compare such a scene with libbox2d, and
// b2dJson (2.4.1's format) cannot hold it, so both refuse it naming each field.
#pragma once

#include "meff/scene.h"

#include <string>
#include <vector>

namespace meff
{

/// One message per capsule or rounded box/polygon ("FILE: bodies[i].shapes[k].FIELD: what it
/// is, which Box2D 2.4.1 does not have; " followed by `consequence`) and per revolute or
/// prismatic joint with its spring on ("FILE: joints[j].enable_spring: ...") and per character
/// ("FILE: characters[c]: ...").
std::vector<std::string> FieldsBox2D241Lacks(const Scene& scene, const std::string& consequence);

} // namespace meff
