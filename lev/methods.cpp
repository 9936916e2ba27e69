#include "lev/methods.h"

#include <stdexcept>

#include "lev/selector_ast.h"
#include "lev/selector_lev.h"
#include "lev/selector_rt.h"

namespace lev {

const std::vector<MethodInfo>& method_table() {
  static const std::vector<MethodInfo> table = {
      {Method::rt, "rt", "RT (every light)", "a shadow ray to every light with non-zero irradiance",
       false},
      {Method::ast, "ast", "AST (Ward 1991)",
       "adaptive shadow testing: test the largest potential contributions until the untested "
       "rest is below the tolerance, estimate the rest from hit ratios",
       true},
      {Method::lev, "lev", "LEV (extent volumes)",
       "walk the light extent volume hierarchy; shadow rays only to the lights returned", true},
  };
  return table;
}

const MethodInfo& method_info(Method method) {
  for (const MethodInfo& info : method_table()) {
    if (info.id == method) return info;
  }
  throw std::logic_error("method missing from method_table");
}

std::optional<Method> parse_method(std::string_view name) {
  for (const MethodInfo& info : method_table()) {
    if (name == info.name) return info.id;
  }
  return std::nullopt;
}

std::string method_names(const char* separator) {
  std::string s;
  for (const MethodInfo& info : method_table()) {
    if (!s.empty()) s += separator;
    s += info.name;
  }
  return s;
}

std::unique_ptr<LightSelector> make_selector(Method method, const LightHierarchy& hierarchy, float tolerance) {
  switch (method) {
    case Method::rt: return std::make_unique<RtSelector>(hierarchy);
    case Method::ast: return std::make_unique<AstSelector>(hierarchy, tolerance);
    case Method::lev: return std::make_unique<LevSelector>(hierarchy, tolerance);
  }
  throw std::logic_error("unknown method");
}

}  // namespace lev
