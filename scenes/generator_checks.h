// What the generated scene classes (stage_rig, ceiling_grid, lamp_street) check of their inputs:
// a parameter out of its range, or a model level out of the class's levels, is one
// std::invalid_argument naming the class, the parameter or level, and the value.
#pragma once

#include <string>

namespace scenes {

// Throws "CLASS: WHAT (VALUE)" unless ok.
void check_generator_parameter(bool ok, const std::string& scene_class, const std::string& what,
                               double value);
// Throws "MODEL level must be MIN..MAX, got LEVEL" outside [min_level, max_level].
void check_model_level(const std::string& model, int level, int min_level, int max_level);

}  // namespace scenes
