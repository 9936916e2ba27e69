// Happens-before annotations for ThreadSanitizer. Debian's oneTBB is not built with TSan, so the
// synchronisation its scheduler provides (the pass's start is visible to every tile task; every
// tile task is finished when parallel_for returns) is invisible to TSan. These calls declare
// exactly those two edges and nothing more: no edge is created between two tile tasks, so a race
// between tiles is still reported. They compile to nothing without -fsanitize=thread.
#pragma once

#if defined(__SANITIZE_THREAD__)
extern "C" void __tsan_acquire(void* address);
extern "C" void __tsan_release(void* address);
#endif

namespace renderer {

inline void annotate_release(void* address) {
#if defined(__SANITIZE_THREAD__)
  __tsan_release(address);
#else
  (void)address;
#endif
}

inline void annotate_acquire(void* address) {
#if defined(__SANITIZE_THREAD__)
  __tsan_acquire(address);
#else
  (void)address;
#endif
}

}  // namespace renderer
