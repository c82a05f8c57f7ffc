// run_with_stack: a POSIX thread with a stack of the size asked for, joined before returning.
#include "core/large_stack.h"

#include <malloc.h>
#include <pthread.h>

#include <exception>

namespace wardray {

namespace {

struct Job {
    const std::function<void(std::size_t)>* work = nullptr;
    std::size_t stack_bytes = 0;
    std::exception_ptr error;
};

void* run_job(void* arg) {
    auto* job = static_cast<Job*>(arg);
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

}  // namespace wardray
