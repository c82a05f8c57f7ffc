// POV-Ray's animation: frames, clocks and frame file names as POV-Ray 3.7 computes them.
#include "app/animation.h"

#include <algorithm>
#include <cstdio>

namespace wardray::app {

namespace {

// A still is an animation only when a frame is given, and not as +KFI1 +KFF1 (which POV-Ray renders as a still).
bool is_animation(const AnimationOptions& a) {
    if (!a.initial_frame && !a.final_frame) return false;
    return !(a.initial_frame && a.final_frame && *a.initial_frame == *a.final_frame);
}

int digit_count(int n) {
    int digits = 1;
    for (n = std::max(n, 0); n >= 10; n /= 10) ++digits;
    return digits;
}

}  // namespace

std::filesystem::path frame_file_name(const std::filesystem::path& output, int number, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%0*d", digits, std::max(number, 0));
    std::filesystem::path named = output.parent_path() / (output.stem().string() + text);
    named += output.extension();
    return named;
}

std::variant<std::vector<Frame>, std::string> plan_frames(const AnimationOptions& a,
                                                          const std::filesystem::path& output) {
    if (!is_animation(a)) {
        Frame still;
        still.clock.clock = a.clock.value_or(0.0);
        still.clock.clock_on = a.clock.has_value();
        still.output = output;
        return std::vector<Frame>{still};
    }
    const int first = a.initial_frame.value_or(1);
    const int last = a.final_frame.value_or(first);
    if (last < first)
        return "the final frame " + std::to_string(last) + " is before the initial frame " + std::to_string(first);
    // POV-Ray compat: a cyclic animation counts one frame more (final_frame reads last + 1) and does not render it,
    // so the clock stops one step short of final_clock and frame 1 can follow the last seamlessly.
    const int counted_last = a.cyclic ? last + 1 : last;
    // POV-Ray gives a one-frame animation a NaN clock; wardray gives it initial_clock (and clock_delta 0).
    const double delta =
        counted_last > first ? (a.final_clock - a.initial_clock) / (counted_last - first) : 0.0;
    const int from = std::max(first, a.subset_start.value_or(first));
    const int to = std::min(last, a.subset_end.value_or(last));
    if (to < from)
        return "no frame of " + std::to_string(first) + ".." + std::to_string(last) + " is in the subset " +
               std::to_string(from) + ".." + std::to_string(to);
    const int digits = digit_count(counted_last);
    std::vector<Frame> frames;
    for (int n = from; n <= to; ++n) {
        Frame f;
        f.number = n;
        f.clock = {.clock = a.initial_clock + (n - first) * delta,
                   .clock_delta = delta,
                   .clock_on = true,
                   .frame_number = static_cast<double>(n),
                   .initial_frame = static_cast<double>(first),
                   .final_frame = static_cast<double>(counted_last),
                   .initial_clock = a.initial_clock,
                   .final_clock = a.final_clock};
        f.output = frame_file_name(output, n, digits);
        frames.push_back(f);
    }
    return frames;
}

}  // namespace wardray::app
