// run_with_stack and unpoison_stack_above_here: work on a large stack, and exceptions thrown from deep in it.
#include "core/large_stack.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>

namespace wardray {
namespace {

// An exception that, as the parser's do, clears the stale stack poison when it is made.
struct DeepError {
    DeepError() noexcept { unpoison_stack_above_here(); }
    int depth = 0;
};

// Keeps the compiler from folding the recursions away and makes their arrays address-taken (so that
// AddressSanitizer surrounds each with poisoned redzones).
__attribute__((noinline)) void touch(volatile char* bytes, std::size_t n) {
    for (std::size_t i = 0; i < n; i += 512) bytes[i] = static_cast<char>(i);
}

// About 4 KB of frame per level; throws at the bottom.
__attribute__((noinline)) int descend_and_throw(int levels) {
    volatile char frame[4000];
    touch(frame, sizeof frame);
    if (levels == 0) {
        DeepError error;
        error.depth = 1;
        throw error;
    }
    return descend_and_throw(levels - 1) + frame[0];
}

// A descent with frames of another size, over the stack the first one unwound: its arrays land on the old
// redzones, which AddressSanitizer would report as a stack-buffer-overflow if they were still poisoned.
__attribute__((noinline)) int descend_again(int levels) {
    volatile char frame[1500];
    touch(frame, sizeof frame);
    for (std::size_t i = 0; i < sizeof frame; ++i) frame[i] = static_cast<char>(i);
    if (levels == 0) return frame[7] == 7 ? 1 : 0;
    return descend_again(levels - 1) + (frame[1] == 1 ? 1 : 0);
}

TEST(LargeStack, WorkRunsWithTheStackAskedFor) {
    std::size_t seen = 1;
    run_with_stack(std::size_t{64} << 20, [&](std::size_t bytes) { seen = bytes; });
    EXPECT_EQ(seen, std::size_t{64} << 20);
}

TEST(LargeStack, AnExceptionIsRethrownOnTheCallingThread) {
    EXPECT_THROW(run_with_stack(std::size_t{8} << 20, [](std::size_t) { throw std::runtime_error("x"); }),
                 std::runtime_error);
}

// Over 64 MB deep, more than AddressSanitizer unpoisons by itself on a throw (google/sanitizers#189): without
// unpoison_stack_above_here, the ASan build reports a false stack-buffer-overflow in descend_again.
TEST(LargeStack, AThrowFromDeepInTheStackLeavesItCleanForWhatRunsNext) {
    int caught_depth = 0;
    int again = 0;
    run_with_stack(std::size_t{1} << 30, [&](std::size_t bytes) {
        ASSERT_GT(bytes, 0u);
        try {
            descend_and_throw(20000);  // about 80 MB
        } catch (const DeepError& e) {
            caught_depth = e.depth;
        }
        again = descend_again(40000);
    });
    EXPECT_EQ(caught_depth, 1);
    EXPECT_EQ(again, 40001);
}

}  // namespace
}  // namespace wardray
