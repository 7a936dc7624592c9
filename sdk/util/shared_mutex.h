// A reader-writer lock in which a waiting writer goes before readers that arrive after it.
// std::shared_mutex on glibc prefers readers: a steady stream of overlapping query batches from
// several threads could hold off a mesh edit forever. Readers must not lock recursively.
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
using SharedMutex = std::shared_mutex;  // elsewhere the platform's own policy applies
#endif

}  // namespace nl
