// libFuzzer entry point: parses arbitrary bytes as a scene, with file writes refused and small guard rails.
//
// Built as a fuzzer with -DWARDRAY_FUZZ=ON under clang (tools/fuzz.sh), and without libFuzzer into
// fuzz_regression_tests, which feeds the regression folder and the seed scenes through the same function.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "parser/parse.h"

namespace {

// Small limits, so one input costs milliseconds: an endless loop or recursion ends quickly and no input
// can ask for much memory.
wardray::parser::ParseOptions fuzz_options() {
    wardray::parser::ParseOptions o;
    o.file_writes = wardray::parser::ParseOptions::FileWrites::Refuse;
    o.max_loop_iterations = 20'000;
    o.max_macro_depth = 40;
    o.max_include_depth = 8;
    o.max_array_elements = 100'000;
    o.max_string_length = 100'000;
    o.max_objects = 20'000;
    o.max_memory_bytes = std::size_t{512} << 20;
    o.image_width = 64;
    o.image_height = 48;
    return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const wardray::parser::ParseOptions options = fuzz_options();
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    // A folder that does not exist: relative #include and #fopen find nothing, absolute ones are refused or
    // read-only.
    wardray::parser::parse_string(text, "/nonexistent/wardray-fuzz/scene.pov", options);
    return 0;
}
