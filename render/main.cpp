// wardray: renders a POV-Ray 3.7 scene file.
#include <string>
#include <vector>

#include "render/app.h"

int main(int argc, char** argv) {
    return wardray::render::run(std::vector<std::string>(argv + 1, argv + argc), argc > 0 ? argv[0] : "wardray");
}
