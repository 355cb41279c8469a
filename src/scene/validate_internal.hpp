// The validator as the loader calls it: told which entities already failed
// the loader's shape checks, so their stand-in defaults raise no geometric
// follow-on errors.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/scene.hpp"

namespace litkit {

// Entity names as in Scene::locations: "room", "observer", "output",
// "lighting", "lights[2]", "objects[0]"; "" for a problem with the file as a
// whole (a missing or misspelt table), which leaves out all geometry.
using BrokenEntities = std::set<std::string, std::less<>>;

std::vector<Diagnostic> validate_scene(const Scene& scene, const BrokenEntities& broken,
                                      std::uint64_t triangle_budget = default_triangle_budget);

}  // namespace litkit
