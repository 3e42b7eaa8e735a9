// The photon flags of objects (object_photons.cpp).
#pragma once

#include <functional>
#include <string>

#include "scene/description.hpp"

namespace povtrace::sdl {

// What a CSG child takes from its parent's photons { } when the parent is placed (POV-Ray's Post_Process): the
// target and its multiplier, pass_through, refraction and reflection where the parent wrote them, collect off;
// CheckPassThru's fix-ups report through `warn`.
void inherit_photon_flags(const ObjectPhotons& parent, ObjectPhotons& child,
                          const std::function<void(const std::string&)>& warn);

}  // namespace povtrace::sdl
