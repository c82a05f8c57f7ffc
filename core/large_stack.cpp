// run_with_stack: a POSIX thread with a stack of the size asked for, joined before returning.
#include "core/large_stack.h"

#include <malloc.h>
#include <pthread.h>

#include <exception>

#include "core/sanitizer.h"

#if __has_include(<sanitizer/asan_interface.h>)
#include <sanitizer/asan_interface.h>
#define WARDRAY_HAVE_ASAN_INTERFACE 1
#endif

namespace wardray {

namespace {

// The highest address of the run_with_stack thread's stack, for unpoison_stack_above_here; null on other threads.
thread_local char* t_stack_top = nullptr;

void record_stack_top() {
    pthread_attr_t attr;
    if (pthread_getattr_np(pthread_self(), &attr) != 0) return;
    void* base = nullptr;
    std::size_t size = 0;
    if (pthread_attr_getstack(&attr, &base, &size) == 0) t_stack_top = static_cast<char*>(base) + size;
    pthread_attr_destroy(&attr);
}

struct Job {
    const std::function<void(std::size_t)>* work = nullptr;
    std::size_t stack_bytes = 0;
    std::exception_ptr error;
};

void* run_job(void* arg) {
    auto* job = static_cast<Job*>(arg);
    if constexpr (k_address_sanitizer) record_stack_top();
    try {
        (*job->work)(job->stack_bytes);
    } catch (...) {
        job->error = std::current_exception();
    }
    return nullptr;
}

}  // namespace

void run_with_stack(std::size_t stack_bytes, const std::function<void(std::size_t)>& work) {
    Job job;
    job.work = &work;
    job.stack_bytes = stack_bytes;
    pthread_attr_t attr;
    bool started = false;
    pthread_t thread{};
    if (pthread_attr_init(&attr) == 0) {
        started = pthread_attr_setstacksize(&attr, stack_bytes) == 0 &&
                  pthread_create(&thread, &attr, &run_job, &job) == 0;
        pthread_attr_destroy(&attr);
    }
    if (!started) {
        work(0);
        return;
    }
    pthread_join(thread, nullptr);
    // The thread allocated from an arena of its own: give its freed pages back, or they stay resident beside the
    // calling thread's arena for the rest of the run.
    malloc_trim(0);
    if (job.error) std::rethrow_exception(job.error);
}

void unpoison_stack_above_here() noexcept {
#if defined(WARDRAY_HAVE_ASAN_INTERFACE)
    if constexpr (k_address_sanitizer) {
        auto* here = static_cast<char*>(__builtin_frame_address(0));
        if (t_stack_top != nullptr && here < t_stack_top)
            __asan_unpoison_memory_region(here, static_cast<std::size_t>(t_stack_top - here));
    }
#endif
}

}  // namespace wardray
