#include "scenes/generator_checks.h"

#include <stdexcept>

namespace scenes {

void check_generator_parameter(bool ok, const std::string& scene_class, const std::string& what,
                               double value) {
  if (!ok)
    throw std::invalid_argument(scene_class + ": " + what + " (" + std::to_string(value) + ")");
}

void check_model_level(const std::string& model, int level, int min_level, int max_level) {
  if (level < min_level || level > max_level) {
    throw std::invalid_argument(model + " level must be " + std::to_string(min_level) + ".." +
                                std::to_string(max_level) + ", got " + std::to_string(level));
  }
}

}  // namespace scenes
