// The method's group of the settings (lev::MethodChoice) compares what its method reads: for
// every method, a change of a setting its row says it reads makes the choices differ, a change
// of one it does not read leaves them equal, and used_settings makes equal choices identical.
#include <gtest/gtest.h>

#include "lev/methods.h"

namespace {

struct Change {
  const char* name;
  bool lev::MethodInfo::*read;  // the row's trait that says the method reads it
  void (*apply)(lev::MethodChoice& choice);
};

const Change kChanges[] = {
    {"tolerance", &lev::MethodInfo::uses_tolerance,
     [](lev::MethodChoice& c) { c.tolerance = 0.25; }},
    {"relative_error", &lev::MethodInfo::uses_relative_error,
     [](lev::MethodChoice& c) { c.relative_error = 0.25; }},
    {"lights_per_point", &lev::MethodInfo::stochastic,
     [](lev::MethodChoice& c) { c.lights_per_point = 5; }},
};

TEST(MethodChoice, ComparesTheSettingsItsMethodReads) {
  int read = 0, ignored = 0;
  for (const lev::MethodInfo& info : lev::method_table()) {
    lev::MethodChoice a;
    a.method = info.id;
    EXPECT_EQ(a, a) << info.name;
    for (const Change& change : kChanges) {
      lev::MethodChoice b = a;
      change.apply(b);
      const bool reads = info.*change.read;
      EXPECT_EQ(a != b, reads) << info.name << " " << change.name;
      EXPECT_EQ(a == b, !reads) << info.name << " " << change.name;
      reads ? ++read : ++ignored;
      if (!reads) {
        const lev::MethodChoice ua = lev::used_settings(a), ub = lev::used_settings(b);
        EXPECT_EQ(ua.tolerance, ub.tolerance) << info.name;
        EXPECT_EQ(ua.relative_error, ub.relative_error) << info.name;
        EXPECT_EQ(ua.lights_per_point, ub.lights_per_point) << info.name;
      }
    }
  }
  // Both sides are exercised: some method reads each kind of setting, some ignores it.
  EXPECT_GT(read, 2);
  EXPECT_GT(ignored, 2);
}

TEST(MethodChoice, AnotherMethodIsAnotherChoice) {
  lev::MethodChoice a, b;
  a.method = lev::Method::lev;
  b.method = lev::Method::rt;
  EXPECT_NE(a, b);
  b.method = lev::Method::lev;
  EXPECT_EQ(a, b);
}

}  // namespace
