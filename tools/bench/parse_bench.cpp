// parse_bench: parses one scene file many times in one process and prints the fastest and median parse time,
// so parser changes can be measured without process start-up in the figure.
//   parse_bench [--eager] FILE [RUNS]
// --eager reads every library declaration in place (as --check does) instead of at its first use.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string_view>
#include <vector>

#include <malloc.h>
#include <sys/resource.h>

#include "parser/parse.h"

int main(int argc, char** argv) {
    const bool eager = argc > 1 && std::string_view(argv[1]) == "--eager";
    if (eager) {
        --argc;
        ++argv;
    }
    if (argc < 2) {
        std::fprintf(stderr, "usage: parse_bench [--eager] FILE [RUNS]\n");
        return 2;
    }
    // As the wardray command does (app/main.cpp): freed blocks stay in the heap for reuse.
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 50;
    wardray::parser::ParseOptions options;
    options.library_paths.push_back("/usr/share/povray-3.7/include");
    options.defer_library_declarations = !eager;
    std::vector<double> seconds;
    long first_faults = 0;
    double first_cpu = 0.0;
    auto cpu_seconds = [] {
        timespec t{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    };
    for (int i = 0; i < runs; ++i) {
        rusage before{};
        getrusage(RUSAGE_SELF, &before);
        const double cpu_start = cpu_seconds();
        const auto start = std::chrono::steady_clock::now();
        const auto result = wardray::parser::parse_file(argv[1], options);
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        rusage after{};
        getrusage(RUSAGE_SELF, &after);
        if (i == 0) {
            first_faults = after.ru_minflt - before.ru_minflt;
            first_cpu = cpu_seconds() - cpu_start;
        }
        if (!result.ok()) {
            std::fprintf(stderr, "parse_bench: %s does not parse\n", argv[1]);
            return 1;
        }
    }
    const double first = seconds.front();
    std::sort(seconds.begin(), seconds.end());
    std::printf("runs %d  first %.4f s (CPU %.4f s, %ld page faults)  fastest %.4f s  median %.4f s\n", runs, first,
                first_cpu, first_faults, seconds.front(), seconds[seconds.size() / 2]);
    return 0;
}
