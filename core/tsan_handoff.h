#pragma once
// ThreadSanitizer annotations for work handed to TBB. Debian's libtbb is not instrumented, so
// TSan cannot see that a parallel_for's tasks start after the caller's writes and end before
// it continues; data made by the caller and used by TBB's already-running workers then looks
// raced. tsan_release/tsan_acquire state that order; without TSan they compile to nothing.
#if defined(__SANITIZE_THREAD__)
#define RAYO_TSAN_ANNOTATIONS 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define RAYO_TSAN_ANNOTATIONS 1
#endif
#endif

#ifdef RAYO_TSAN_ANNOTATIONS
extern "C" void __tsan_acquire(void* addr);
extern "C" void __tsan_release(void* addr);
#endif

namespace rayo {

// Everything this thread did so far happens before a later tsan_acquire on the same token.
inline void tsan_release([[maybe_unused]] void* token) {
#ifdef RAYO_TSAN_ANNOTATIONS
    __tsan_release(token);
#endif
}

inline void tsan_acquire([[maybe_unused]] void* token) {
#ifdef RAYO_TSAN_ANNOTATIONS
    __tsan_acquire(token);
#endif
}

}  // namespace rayo
