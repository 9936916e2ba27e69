// The table of many-light methods: one row per method, read by the CLI, the viewer and the
// benchmarks, so a new method appears everywhere once it is added here.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

enum class Method { rt, ast, lev };

struct MethodInfo {
  Method id;
  const char* name;   // CLI value and stats JSON
  const char* label;  // viewer
  const char* summary;
  bool uses_tolerance;  // false: the images do not depend on the tolerance (no restart, no refit)
};

const std::vector<MethodInfo>& method_table();
const MethodInfo& method_info(Method method);
std::optional<Method> parse_method(std::string_view name);
std::string method_names(const char* separator);  // "rt|ast|lev"

// The selector for one render at one tolerance. It reads the hierarchy (which it never changes,
// so any number of selectors may share it) and must not outlive it.
std::unique_ptr<LightSelector> make_selector(Method method, const LightHierarchy& hierarchy, float tolerance);

}  // namespace lev
