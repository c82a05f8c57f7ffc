// Tests of the option table: INI settings set what their switches set, and the table is whole and unambiguous.
#include "app/option_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

namespace wardray::app {
namespace {

Options from_switches(const std::vector<std::string>& args) {
    auto r = parse_command_line(args);
    EXPECT_TRUE(std::holds_alternative<Options>(r))
        << (std::holds_alternative<UsageError>(r) ? std::get<UsageError>(r).message : "");
    return std::holds_alternative<Options>(r) ? std::get<Options>(r) : Options{};
}

Options from_ini(const std::string& key, const std::string& value) {
    Options o;
    const auto error = apply_ini_setting(key, value, o);
    EXPECT_FALSE(error.has_value()) << key << "=" << value << ": " << (error ? error->message : "");
    return o;
}

std::string ini_error(const std::string& key, const std::string& value) {
    Options o;
    const auto error = apply_ini_setting(key, value, o);
    EXPECT_TRUE(error.has_value()) << key << "=" << value;
    return error ? error->message : "";
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

TEST(OptionTable, WidthFromAnIniSettingIsWidthFromTheSwitch) {
    const Options ini = from_ini("Width", "640");
    EXPECT_EQ(ini.width, 640);
    EXPECT_EQ(ini, from_switches({"+W640"}));
    EXPECT_NE(ini, Options{});
    EXPECT_EQ(from_ini("width", "64"), from_switches({"+w64"}));  // INI keys, like switches, ignore case
}

TEST(OptionTable, EveryIniKeySetsWhatItsSwitchSets) {
    struct Case {
        const char* key;
        const char* value;
        const char* switch_text;
    };
    const Case cases[] = {
        {"Height", "480", "+H480"},           {"Antialias", "on", "+A"},
        {"Antialias", "off", "-A"},           {"Antialias_Depth", "4", "+R4"},
        {"Antialias_Gamma", "2.2", "+AG2.2"}, {"Sampling_Method", "1", "+AM1"},
        {"Jitter", "off", "-J"},              {"Jitter_Amount", "0.5", "+J0.5"},
        {"Output_File_Type", "E", "+FE"},     {"Output_To_File", "off", "-F"},
        {"Output_File_Name", "o.exr", "+Oo.exr"}, {"Input_File_Name", "s.pov", "+Is.pov"},
        {"Library_Path", "/tmp/inc", "+L/tmp/inc"}, {"Work_Threads", "3", "+WT3"},
        {"Display", "off", "-D"},             {"Verbose", "yes", "+V"},
        {"Radiosity_From_File", "true", "+RFI"}, {"Radiosity_To_File", "1", "+RFO"},
        {"Radiosity_File_Name", "c.rca", "+RFc.rca"}, {"Declare", "Count=12", "Declare=Count=12"},
    };
    for (const Case& c : cases) EXPECT_EQ(from_ini(c.key, c.value), from_switches({c.switch_text})) << c.key;
}

TEST(OptionTable, AThresholdAloneLeavesAntialiasingAsItWas) {
    // POV-Ray's Antialias_Threshold sets the threshold only; Antialias turns antialiasing on or off.
    const Options o = from_ini("Antialias_Threshold", "0.2");
    EXPECT_DOUBLE_EQ(o.antialias_threshold, 0.2);
    EXPECT_FALSE(o.antialias);
    EXPECT_TRUE(from_switches({"+A0.2"}).antialias);
}

TEST(OptionTable, UnknownKeysAndWrongValuesAreClearErrors) {
    const std::string unknown = ini_error("Frobnicate", "3");
    EXPECT_NE(unknown.find("unknown INI key"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("Frobnicate"), std::string::npos) << unknown;
    EXPECT_NE(ini_error("Width", "abc").find("'Width=abc': expected a size in pixels"), std::string::npos);
    EXPECT_NE(ini_error("Width", "0").find("1..65536"), std::string::npos);
    EXPECT_NE(ini_error("Antialias", "maybe").find("on or off"), std::string::npos);
    EXPECT_NE(ini_error("Height", "").find("expected a value"), std::string::npos);
    EXPECT_NE(ini_error("Declare", "X").find("Declare=NAME=NUMBER"), std::string::npos);
    EXPECT_NE(ini_error("Output_File_Type", "T").find("+FN"), std::string::npos);
    // A long option is not an INI key.
    EXPECT_NE(ini_error("threads", "2").find("unknown INI key"), std::string::npos);
}

TEST(OptionTable, EverySpellingIsTakenOnceAndFindsItsEntry) {
    std::set<std::string> letters, ini_keys, long_names;
    for (const OptionSpec& spec : option_table()) {
        ASSERT_NE(spec.set, nullptr) << spec.usage;
        // An entry without a --help line of its own is named on a neighbour's line or in the closing list.
        if (spec.usage.empty()) {
            const std::string_view name = spec.letters.empty() ? (spec.ini_key.empty() ? spec.ini_flag : spec.ini_key)
                                                               : spec.letters;
            EXPECT_NE(usage_text().find(std::string(name)), std::string::npos) << name;
        }
        EXPECT_FALSE(spec.letters.empty() && spec.ini_key.empty() && spec.ini_flag.empty() && spec.long_name.empty())
            << spec.usage;
        if (!spec.letters.empty()) {
            EXPECT_TRUE(letters.insert(lower(spec.letters)).second) << spec.letters;
            EXPECT_EQ(find_switch(spec.letters), &spec) << spec.letters;
        }
        for (const std::string_view key : {spec.ini_key, spec.ini_flag}) {
            if (key.empty()) continue;
            EXPECT_TRUE(ini_keys.insert(lower(key)).second) << key;
            bool is_flag_key = false;
            EXPECT_EQ(find_ini_key(key, is_flag_key), &spec) << key;
            EXPECT_EQ(is_flag_key, key == spec.ini_flag) << key;
        }
        for (const std::string_view name : {spec.long_name, spec.short_name}) {
            if (name.empty()) continue;
            EXPECT_TRUE(long_names.insert(std::string(name)).second) << name;
            EXPECT_EQ(find_long_option(name), &spec) << name;
        }
    }
    EXPECT_GE(letters.size(), 17u);
    EXPECT_GE(ini_keys.size(), 20u);
}

TEST(OptionTable, SwitchesMatchTheirLongestLetters) {
    EXPECT_EQ(find_switch("WT2")->letters, "WT");
    EXPECT_EQ(find_switch("w2")->letters, "W");
    EXPECT_EQ(find_switch("AG2.2")->letters, "AG");
    EXPECT_EQ(find_switch("A0.3")->letters, "A");
    EXPECT_EQ(find_switch("RFI")->letters, "RFI");
    // RFI takes nothing, so +RFIname names a radiosity file "Iname", as before.
    EXPECT_EQ(find_switch("RFIname")->letters, "RF");
    EXPECT_EQ(from_switches({"+RFIname"}).radiosity_file->string(), "Iname");
    EXPECT_EQ(find_switch("KFF20")->letters, "KFF");
    EXPECT_EQ(find_switch("KF0.5")->letters, "KF");
    EXPECT_EQ(find_switch("K0.5")->letters, "K");
    EXPECT_EQ(find_switch("ZZ9"), nullptr);
}

TEST(OptionTable, HelpListsEveryOptionOnLinesOfAtMost120Columns) {
    const std::string help = usage_text();
    EXPECT_EQ(help.rfind("usage: wardray", 0), 0u);
    for (const OptionSpec& spec : option_table())
        EXPECT_NE(help.find("  " + std::string(spec.usage) + " "), std::string::npos) << spec.usage;
    // tools/compare/renderers.py looks for these two to know the reference mode exists.
    EXPECT_NE(help.find("--gi-rays"), std::string::npos);
    EXPECT_NE(help.find("reference"), std::string::npos);
    std::istringstream lines(help);
    for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 120u) << line;
}

}  // namespace
}  // namespace wardray::app
