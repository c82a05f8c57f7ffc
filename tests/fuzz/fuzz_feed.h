// What the fuzz regression tests share: the files of a folder in a repeatable order, and feeding one file through
// the linked fuzzer's entry point (LLVMFuzzerTestOneInput) within a few seconds.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace wardray::test {

/// Every regular file below `dir` (recursively) with `extension` (any when null), sorted so runs are repeatable.
inline std::vector<std::filesystem::path> files_under(const std::filesystem::path& dir, const char* extension) {
    std::vector<std::filesystem::path> files;
    if (!std::filesystem::is_directory(dir)) return files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        if (e.is_regular_file() && (extension == nullptr || e.path().extension() == extension))
            files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

/// One input through the entry point: it must return 0 (a crash, or the fuzzer's own abort, ends the test
/// binary) within a few seconds, since an input this slow is a hang for the fuzzer.
inline void feed(const std::filesystem::path& file) {
    SCOPED_TRACE(file.string());
    std::ifstream f(file, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    const std::string bytes = s.str();
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0) << "an input this slow is a hang for the fuzzer";
}

}  // namespace wardray::test
