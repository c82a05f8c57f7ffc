// wardray: renders a POV-Ray 3.7 scene file.
#include <cstdio>
#include <malloc.h>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "app/app.h"

int main(int argc, char** argv) {
    // A first touch of a fresh page costs about 11 us on our VMs, and a parse frees and allocates token arrays
    // of hundreds of KB: keep freed blocks up to 1 MB in the heap for reuse rather than returning them to the
    // system (mapped anew and faulted again). Worth about 1 ms of a 6 ms library-heavy parse. Larger blocks (object
    // lists, an image's texels, a large file's tokens) are mapped: kept in the heap they stayed resident after use
    // and fragmented it (up to 40 % of a 40,000-sphere scene's peak memory at a 32 MB threshold).
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    // Running out of memory (a scene far larger than the machine) is the scene's failure, not a crash.
    try {
        return wardray::app::run(std::vector<std::string>(argv + 1, argv + argc), argc > 0 ? argv[0] : "wardray");
    } catch (const std::bad_alloc&) {
        std::fputs("wardray: error: out of memory\n", stderr);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "wardray: error: %s\n", e.what());
    }
    return wardray::app::kExitScene;
}
