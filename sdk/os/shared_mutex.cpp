#include "os/shared_mutex.h"

#include <cstring>
#include <system_error>

#include "util/error.h"

namespace nl {
namespace {

// The locks this thread holds, in the order taken. NavLink nests at most a few (agents, navmeshes,
// level), so a small fixed array: locking never allocates.
struct HeldLocks {
    static constexpr int capacity = 16;
    const SharedMutex* locks[capacity];
    int count = 0;

    bool contains(const SharedMutex* m) const noexcept {
        for (int i = 0; i < count; ++i)
            if (locks[i] == m) return true;
        return false;
    }
    void remove(const SharedMutex* m) noexcept {
        for (int i = count - 1; i >= 0; --i) {
            if (locks[i] != m) continue;
            for (int j = i; j + 1 < count; ++j) locks[j] = locks[j + 1];
            --count;
            return;
        }
    }
};

thread_local HeldLocks held;

// refuse_if_held made room.
void note_taken(const SharedMutex* m) noexcept { held.locks[held.count++] = m; }

#if defined(__GLIBC__)
void check(int error, const char* operation, const char* what) {
    if (error) fail(ErrorCode::Internal, "locking ", what, ": ", operation, " failed: ", std::strerror(error));
}
#endif

}  // namespace

#if defined(__GLIBC__)
SharedMutex::SharedMutex(const char* what) : what_(what) {
    pthread_rwlockattr_t attributes;
    pthread_rwlockattr_init(&attributes);
    pthread_rwlockattr_setkind_np(&attributes, PTHREAD_RWLOCK_PREFER_WRITER_NONRECURSIVE_NP);
    const int error = pthread_rwlock_init(&lock_, &attributes);
    pthread_rwlockattr_destroy(&attributes);
    if (error) throw std::system_error(error, std::generic_category(), "pthread_rwlock_init");
}

SharedMutex::~SharedMutex() { pthread_rwlock_destroy(&lock_); }

void SharedMutex::lock() {
    refuse_if_held("for writing");
    check(pthread_rwlock_wrlock(&lock_), "pthread_rwlock_wrlock", what_);
    note_taken(this);
}

void SharedMutex::lock_shared() {
    refuse_if_held("for reading");
    check(pthread_rwlock_rdlock(&lock_), "pthread_rwlock_rdlock", what_);
    note_taken(this);
}

void SharedMutex::unlock() {
    held.remove(this);
    pthread_rwlock_unlock(&lock_);  // cannot fail: this thread holds it (std's lock guards see to it)
}

void SharedMutex::unlock_shared() { unlock(); }
#else
SharedMutex::SharedMutex(const char* what) : what_(what) {}

SharedMutex::~SharedMutex() = default;

void SharedMutex::lock() {
    refuse_if_held("for writing");
    lock_.lock();
    note_taken(this);
}

void SharedMutex::lock_shared() {
    refuse_if_held("for reading");
    lock_.lock_shared();
    note_taken(this);
}

void SharedMutex::unlock() {
    held.remove(this);
    lock_.unlock();
}

void SharedMutex::unlock_shared() {
    held.remove(this);
    lock_.unlock_shared();
}
#endif

bool SharedMutex::held_by_this_thread() const noexcept { return held.contains(this); }

void SharedMutex::refuse_if_held(const char* mode) const {
    if (held.contains(this))
        fail(ErrorCode::Internal, "NavLink was called back on a thread that holds the lock of ", what_,
             " (taking it again ", mode,
             " would deadlock or break it): a task, progress or log callback "
             "must not call NavLink functions that lock what the call it runs under holds (navlink.h, "
             "\"Callbacks\")");
    if (held.count == HeldLocks::capacity)
        fail(ErrorCode::Internal, "a thread holds ", HeldLocks::capacity, " of NavLink's locks at once (taking ", what_,
             "'s)");
}

}  // namespace nl
