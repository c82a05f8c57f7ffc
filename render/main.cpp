// wardray: renders a POV-Ray 3.7 scene file.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "render/app.h"

int main(int argc, char** argv) {
    // Running out of memory (a scene far larger than the machine) is the scene's failure, not a crash.
    try {
        return wardray::render::run(std::vector<std::string>(argv + 1, argv + argc), argc > 0 ? argv[0] : "wardray");
    } catch (const std::bad_alloc&) {
        std::fputs("wardray: error: out of memory\n", stderr);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "wardray: error: %s\n", e.what());
    }
    return wardray::render::kExitScene;
}
