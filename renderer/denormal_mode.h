// Flush-to-zero and denormals-are-zero while a tile's rays are cast (Embree's advice), restored
// afterwards so the calling thread's mode is left as it was. Shared by the render and the bare
// ray loop of ray_log.h, so both cast under the same floating-point mode.
#pragma once

#include <pmmintrin.h>
#include <xmmintrin.h>

namespace renderer {

class DenormalModeGuard {
 public:
  DenormalModeGuard() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }
  ~DenormalModeGuard() { _mm_setcsr(saved_); }
  DenormalModeGuard(const DenormalModeGuard&) = delete;
  DenormalModeGuard& operator=(const DenormalModeGuard&) = delete;

 private:
  unsigned saved_;
};

}  // namespace renderer
