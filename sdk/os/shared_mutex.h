// nl::SharedMutex: a reader-writer lock in which a waiting writer goes before readers that arrive
// after it, and which refuses to be taken again by a thread that holds it.
//
// Writers first: the level's lock needs this. Query batches from several threads overlap all the time,
// and with a lock that lets new readers in while a writer waits, a steady stream of them holds off a
// mesh edit forever. On glibc, std::shared_mutex is a pthread rwlock of glibc's default kind, which
// prefers readers; the writer-preferring kind (PTHREAD_RWLOCK_PREFER_WRITER_NONRECURSIVE_NP) is a glibc
// extension, set here. Elsewhere: std::shared_mutex, whose policy is the platform's. Windows' SRW locks
// and macOS's and musl's rwlocks do not starve writers this way, as far as their documentation goes,
// but only glibc is tested (docs/platforms.md).
//
// Never taken twice by one thread: a host callback that NavLink calls while it holds a lock (a task
// callback during nl_world_step, a progress callback during generation) may call back into NavLink on
// the same thread. Taken again there, a rwlock either deadlocks (a read lock under a waiting writer, a
// write lock under one's own read lock) or, as glibc does for a read lock under one's own write lock,
// fails with EDEADLK, which a lock guard cannot report: the call would run unlocked and its unlock
// would release the outer holder's lock. So each thread keeps the locks it holds, and taking one of
// them again throws ErrorCode::Internal naming the lock (`what` at construction) before touching it;
// so does any error the platform's lock returns. Nothing is locked when it throws.
#pragma once

#include <mutex>
#include <shared_mutex>  // std::shared_lock and std::unique_lock take it

#if defined(__GLIBC__)
#include <pthread.h>
#endif

namespace nl {

class SharedMutex {
public:
    // `what` names what the lock guards, in an error message ("the agents"); a string literal.
    explicit SharedMutex(const char* what);
    ~SharedMutex();
    SharedMutex(const SharedMutex&) = delete;
    SharedMutex& operator=(const SharedMutex&) = delete;

    void lock();
    void unlock();
    void lock_shared();
    void unlock_shared();

    // True when the calling thread holds this lock, shared or exclusive.
    bool held_by_this_thread() const noexcept;

private:
    void refuse_if_held(const char* mode) const;

    const char* what_;
#if defined(__GLIBC__)
    pthread_rwlock_t lock_;
#else
    std::shared_mutex lock_;  // untested: see above
#endif
};

}  // namespace nl
