// nl::SharedMutex: a reader-writer lock in which a waiting writer goes before readers that arrive
// after it. The level's lock needs this: query batches from several threads overlap all the time, and
// with a lock that lets new readers in while a writer waits, a steady stream of them holds off a mesh
// edit forever. Readers must not lock recursively (a waiting writer would deadlock them).
//
// glibc: std::shared_mutex is a pthread rwlock of glibc's default kind, which prefers readers; the
// writer-preferring kind (PTHREAD_RWLOCK_PREFER_WRITER_NONRECURSIVE_NP) is a glibc extension, set here.
// Elsewhere: std::shared_mutex, whose policy is the platform's. Windows' SRW locks and macOS's and musl's
// rwlocks do not starve writers this way, as far as their documentation goes, but only glibc is tested
// (docs/platforms.md); a platform whose lock starves writers would show it as a mesh edit (nl_mesh_*)
// that waits as long as queries keep coming.
#pragma once

#include <shared_mutex>

#if defined(__GLIBC__)
#include <pthread.h>

#include <system_error>
#endif

namespace nl {

#if defined(__GLIBC__)
class SharedMutex {
public:
    SharedMutex() {
        pthread_rwlockattr_t attributes;
        pthread_rwlockattr_init(&attributes);
        pthread_rwlockattr_setkind_np(&attributes, PTHREAD_RWLOCK_PREFER_WRITER_NONRECURSIVE_NP);
        const int error = pthread_rwlock_init(&lock_, &attributes);
        pthread_rwlockattr_destroy(&attributes);
        if (error) throw std::system_error(error, std::generic_category(), "pthread_rwlock_init");
    }
    ~SharedMutex() { pthread_rwlock_destroy(&lock_); }
    SharedMutex(const SharedMutex&) = delete;
    SharedMutex& operator=(const SharedMutex&) = delete;

    void lock() { pthread_rwlock_wrlock(&lock_); }
    void unlock() { pthread_rwlock_unlock(&lock_); }
    void lock_shared() { pthread_rwlock_rdlock(&lock_); }
    void unlock_shared() { pthread_rwlock_unlock(&lock_); }

private:
    pthread_rwlock_t lock_;
};
#else
using SharedMutex = std::shared_mutex;  // untested: see above
#endif

}  // namespace nl
