// Happens-before edges for ThreadSanitizer where synchronisation happens inside libraries it cannot
// see: Debian's TBB is not instrumented, so TSan would not know that a parallel_for's bodies start
// after the caller's writes and finish before it reads their results, and would report those as
// races. The edges name exactly what TBB guarantees (and nothing between bodies), so a real race
// between two bodies is still reported. Nothing at all in other builds.
#pragma once

#if defined(__SANITIZE_THREAD__)
#define NAVLINK_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define NAVLINK_TSAN 1
#endif
#endif

#if defined(NAVLINK_TSAN)
extern "C" void __tsan_acquire(void* address);
extern "C" void __tsan_release(void* address);
#endif

namespace nl {

// What the calling thread did so far happens before whatever acquires `sync` afterwards.
inline void tsan_release([[maybe_unused]] void* sync) {
#if defined(NAVLINK_TSAN)
    __tsan_release(sync);
#endif
}

// Everything released on `sync` so far happens before what the calling thread does next.
inline void tsan_acquire([[maybe_unused]] void* sync) {
#if defined(NAVLINK_TSAN)
    __tsan_acquire(sync);
#endif
}

}  // namespace nl
