// Helpers shared by the parser tests: parse a snippet and read its diagnostics.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "parser/parse.h"

namespace wardray::parser::test {

inline ParseOptions default_options() {
    ParseOptions o;
    o.library_paths = {"/usr/share/povray-3.7/include"};
    return o;
}

/// All diagnostics of a result, formatted, for failure messages and golden comparisons.
inline std::string all_diagnostics(const ParseResult& r) {
    std::string s;
    for (const auto& d : r.diagnostics) s += format_diagnostic(d);
    return s;
}

inline std::size_t count_errors(const ParseResult& r) {
    std::size_t n = 0;
    for (const auto& d : r.diagnostics) n += d.severity == Severity::Error ? 1 : 0;
    return n;
}

/// Parses `text` (with `global_settings { assumed_gamma 1 }` prepended unless asked not to) and expects success.
inline Scene parse_ok(const std::string& text, ParseOptions options = default_options()) {
    const ParseResult r = parse_string("global_settings { assumed_gamma 1.0 }\n" + text, "test.pov", options);
    EXPECT_TRUE(r.ok()) << all_diagnostics(r);
    return r.scene.value_or(Scene{});
}

/// Parses `text` as is, expecting failure.
inline ParseResult parse_fail(const std::string& text, ParseOptions options = default_options()) {
    ParseResult r = parse_string(text, "test.pov", options);
    EXPECT_FALSE(r.ok());
    return r;
}

// A fresh folder for include files, removed at the end of the test.
class TempDir {
public:
    TempDir() {
        m_path = std::filesystem::temp_directory_path() /
                 ("wardray_parser_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(m_path);
        std::filesystem::create_directories(m_path);
    }
    ~TempDir() { std::filesystem::remove_all(m_path); }
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const auto p = m_path / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p) << text;
        return p;
    }
    const std::filesystem::path& path() const { return m_path; }

private:
    std::filesystem::path m_path;
};

}  // namespace wardray::parser::test
