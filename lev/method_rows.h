// The seam through which a program adds methods of its own to method_table() (lev/methods.h)
// without a mutable registry: the table is built once, from the built-in rows and then these.
// The library's definition adds none; a program (a test binary with a method of its own) that
// defines this function replaces it at link time. The rows' ids are set to the next values.
#pragma once

#include <vector>

#include "lev/methods.h"

namespace lev {

std::vector<MethodInfo> extra_method_rows();

}  // namespace lev
