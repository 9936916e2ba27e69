#include "scenes/gltf_refusal.h"

#include <sstream>
#include <stdexcept>

namespace scenes {

void fail_gltf(const std::string& path, const std::string& where, const std::string& value) {
  throw std::invalid_argument(path + ": " + where + ": " + value);
}

std::string gltf_number_text(double value) {
  std::ostringstream out;
  out.precision(9);
  out << value;
  return out.str();
}

}  // namespace scenes
