// POV-Ray's animation, partial-render and front-end options: a second part of the option table.
#include <cctype>
#include <string>

#include "app/option_table.h"

namespace wardray::app {

namespace {

using Why = std::optional<std::string>;
using K = ValueKind;
using U = const OptionUse&;

Why set_int(std::string_view text, int low, int high, const char* why, int& out) {
    int n = 0;
    if (!parse_int(text, n) || n < low || n > high) return why;
    out = n;
    return std::nullopt;
}

Why set_frame(std::string_view text, std::optional<int>& out) {
    int n = 0;
    if (auto why = set_int(text, -999999, 999999, "expected a frame number", n)) return why;
    out = n;
    return std::nullopt;
}

Why set_number(std::string_view text, const char* why, double& out) {
    double v = 0.0;
    if (!parse_double(text, v)) return why;
    out = v;
    return std::nullopt;
}

// +SR/+ER/+SC/+EC: a fraction of the image or a 1-based pixel number, resolved against the size later.
Why set_region_edge(std::string_view text, std::optional<double>& out) {
    double v = 0.0;
    if (!parse_double(text, v) || v < 0.0) return "expected a row or column (a pixel number, or a fraction 0..1)";
    out = v;
    return std::nullopt;
}

// POV-Ray's +Q0..+Q11 (lighting/quality.h): 9 and above are all the same in POV-Ray 3.7.
Why set_quality(U u, Options& o) {
    return set_int(u.value, 0, 11, "expected a quality 0..11", o.quality);
}

Why set_output_alpha(U u, Options& o) {
    o.output_alpha = u.sign.value_or(true);
    return std::nullopt;
}

// What a switch's sign or an INI key's value says, as text: "on"/"off" for a sign alone.
std::string value_text(U u) {
    if (!u.value.empty()) return std::string(u.value);
    return u.sign.value_or(true) ? "on" : "off";
}

// Whether `value` is the setting's neutral value (the one that changes nothing wardray renders).
bool is_neutral(std::string_view value, std::string_view neutral) {
    if (value.empty() || equals_ci(value, neutral)) return true;
    const auto a = parse_ini_bool(value), b = parse_ini_bool(neutral);
    if (a && b) return *a == *b;
    double x = 0.0, y = 0.0;
    return parse_double(value, x) && parse_double(neutral, y) && x == y;
}

// A POV-Ray setting wardray does not implement: accepted as it is at its neutral value, a warning otherwise.
Why unsupported(U u, Options& o, std::string_view name, std::string_view neutral) {
    const std::string value = value_text(u);
    if (!is_neutral(value, neutral))
        o.warnings.push_back(std::string(name) + "=" + value + " is not supported yet; ignored");
    return std::nullopt;
}

// Settings that concern only POV-Ray's display, console, pauses and speed: accepted, and nothing to do.
Why quiet(U, Options&) {
    return std::nullopt;
}

// POV-Ray's animation and partial-render switches first (with --help lines), then what only POV-Ray's front end
// uses (accepted silently) and what wardray does not do yet (a warning unless it is at its neutral value).
constexpr OptionSpec kFrameOptions[] = {
    {.letters = "KFI", .ini_key = "Initial_Frame", .kind = K::Value, .usage = "+KFIn, +KFFn",
     .help = "animation: render frames n..m (named scene1.png .. sceneN.png,\n"
             "zero-padded to the last frame's digits), the scene parsed per frame",
     .set = [](U u, Options& o) { return set_frame(u.value, o.animation.initial_frame); }},
    {.letters = "KFF", .ini_key = "Final_Frame", .kind = K::Value,
     .set = [](U u, Options& o) { return set_frame(u.value, o.animation.final_frame); }},
    {.letters = "KI", .ini_key = "Initial_Clock", .kind = K::Value, .usage = "+KIn, +KFn",
     .help = "clock from n (0) at the first frame to m (1) at the last",
     .set = [](U u, Options& o) { return set_number(u.value, "expected a clock value", o.animation.initial_clock); }},
    {.letters = "KF", .ini_key = "Final_Clock", .kind = K::Value,
     .set = [](U u, Options& o) { return set_number(u.value, "expected a clock value", o.animation.final_clock); }},
    {.letters = "KC", .ini_flag = "Cyclic_Animation", .kind = K::Flag, .usage = "+KC",
     .help = "cyclic: the last frame stops one clock step short of m",
     .set = [](U u, Options& o) {
         o.animation.cyclic = u.sign.value_or(true);
         return u.value.empty() ? Why{} : Why{"takes no value"};
     }},
    {.letters = "SF", .ini_key = "Subset_Start_Frame", .kind = K::Value, .usage = "+SFn, +EFn",
     .help = "render only frames n..m of the animation",
     .set = [](U u, Options& o) { return set_frame(u.value, o.animation.subset_start); }},
    {.letters = "EF", .ini_key = "Subset_End_Frame", .kind = K::Value,
     .set = [](U u, Options& o) { return set_frame(u.value, o.animation.subset_end); }},
    {.letters = "K", .ini_key = "Clock", .kind = K::Value, .usage = "+Kc",
     .help = "a still image's clock (0)",
     .set = [](U u, Options& o) {
         double c = 0.0;
         if (auto why = set_number(u.value, "expected a clock value", c)) return why;
         o.animation.clock = c;
         return Why{};
     }},
    {.letters = "SR", .ini_key = "Start_Row", .kind = K::Value, .usage = "+SRn +ERn +SCn +ECn",
     .help = "render only rows/columns n..m (pixel numbers from 1, or fractions\n"
             "0..1 of the image); the rest of the image is written black",
     .set = [](U u, Options& o) { return set_region_edge(u.value, o.region.start_row); }},
    {.letters = "ER", .ini_key = "End_Row", .kind = K::Value,
     .set = [](U u, Options& o) { return set_region_edge(u.value, o.region.end_row); }},
    {.letters = "SC", .ini_key = "Start_Column", .kind = K::Value,
     .set = [](U u, Options& o) { return set_region_edge(u.value, o.region.start_column); }},
    {.letters = "EC", .ini_key = "End_Column", .kind = K::Value,
     .set = [](U u, Options& o) { return set_region_edge(u.value, o.region.end_column); }},
    {.letters = "C", .ini_flag = "Continue_Trace", .kind = K::Flag, .usage = "+C",
     .help = "continue: frames whose image exists are not rendered again",
     .set = [](U u, Options& o) {
         o.continue_trace = u.sign.value_or(true);
         return u.value.empty() ? Why{} : Why{"takes no value"};
     }},
    {.letters = "UA", .ini_flag = "Output_Alpha", .kind = K::Flag, .usage = "+UA",
     .help = "alpha channel: PNG (and EXR) with alpha where the background shows, as POV-Ray",
     .set = set_output_alpha},
    {.letters = "Q", .ini_key = "Quality", .kind = K::Value, .usage = "+Qn",
     .help = "quality 0..11 (9), as POV-Ray 3.7: 0-1 pigments only, 2-3 no shadows, 4 no\n"
             "area lights, 5 no refraction, 6-7 no reflection or normals, 8 no media,\n"
             "fog, radiosity or photons",
     .set = set_quality},
    {.letters = "BS", .ini_key = "Render_Block_Size", .kind = K::Value, .usage = "+BSn",
     .help = "render block size (32), the unit of antialiasing decisions",
     .set = [](U u, Options& o) {
         return set_int(u.value, 4, 4096, "expected a block size 4..4096", o.render_block_size);
     }},
    // POV-Ray's display, console, pause, abort, bounding and memory settings: nothing to do.
    {.letters = "P", .ini_flag = "Pause_When_Done", .kind = K::Flag, .set = quiet},
    {.letters = "X", .ini_flag = "Test_Abort", .kind = K::FlagValue, .set = quiet},
    {.ini_key = "Test_Abort_Count", .kind = K::Value, .set = quiet},
    {.letters = "SP", .ini_key = "Preview_Start_Size", .kind = K::Value, .set = quiet},
    {.letters = "EP", .ini_key = "Preview_End_Size", .kind = K::Value, .set = quiet},
    {.ini_key = "Palette", .kind = K::Value, .set = quiet},
    {.ini_key = "Video_Mode", .kind = K::Value, .set = quiet},
    {.letters = "UD", .ini_flag = "Draw_Vistas", .kind = K::Flag, .set = quiet},
    {.letters = "GA", .ini_key = "All_File", .ini_flag = "All_Console", .kind = K::FlagValue, .set = quiet},
    {.letters = "GD", .ini_key = "Debug_File", .ini_flag = "Debug_Console", .kind = K::FlagValue, .set = quiet},
    {.letters = "GF", .ini_key = "Fatal_File", .ini_flag = "Fatal_Console", .kind = K::FlagValue, .set = quiet},
    {.letters = "GR", .ini_key = "Render_File", .ini_flag = "Render_Console", .kind = K::FlagValue, .set = quiet},
    {.letters = "GS", .ini_key = "Statistic_File", .ini_flag = "Statistic_Console", .kind = K::FlagValue,
     .set = quiet},
    {.letters = "GW", .ini_key = "Warning_File", .ini_flag = "Warning_Console", .kind = K::FlagValue, .set = quiet},
    {.letters = "MB", .ini_key = "Bounding_Threshold", .ini_flag = "Bounding", .kind = K::FlagValue, .set = quiet},
    {.ini_key = "Bounding_Method", .kind = K::Value, .set = quiet},
    {.letters = "UL", .ini_flag = "Light_Buffer", .kind = K::Flag, .set = quiet},
    {.letters = "UV", .ini_flag = "Vista_Buffer", .kind = K::Flag, .set = quiet},
    {.letters = "UR", .ini_flag = "Remove_Bounds", .kind = K::Flag, .set = quiet},
    {.letters = "SU", .ini_flag = "Split_Unions", .kind = K::Flag, .set = quiet},
    {.letters = "HR", .ini_flag = "High_Reproducibility", .kind = K::Flag, .set = quiet},
    {.ini_flag = "Radiosity_Vain_Pretrace", .kind = K::Flag, .set = quiet},
    {.ini_key = "Render_Pattern", .kind = K::Value, .set = quiet},
    {.ini_key = "Render_Block_Step", .kind = K::Value, .set = quiet},
    {.ini_flag = "Buffer_Output", .kind = K::Flag, .set = quiet},
    {.ini_key = "Buffer_Size", .kind = K::Value, .set = quiet},
    {.ini_key = "Max_Image_Buffer_Memory", .kind = K::Value, .set = quiet},
    {.ini_key = "Pre_Scene_Return", .kind = K::Value, .set = quiet},
    {.ini_key = "Pre_Frame_Return", .kind = K::Value, .set = quiet},
    {.ini_key = "Post_Frame_Return", .kind = K::Value, .set = quiet},
    {.ini_key = "Post_Scene_Return", .kind = K::Value, .set = quiet},
    {.ini_key = "User_Abort_Return", .kind = K::Value, .set = quiet},
    {.ini_key = "Fatal_Error_Return", .kind = K::Value, .set = quiet},
    // POV-Ray settings wardray does not implement: a warning unless at the value that changes nothing.
    {.letters = "MV", .ini_key = "Version", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Version", "3.7"); }},
    {.letters = "GI", .ini_key = "Create_Ini", .kind = K::FlagValue,
     .set = [](U u, Options& o) { return unsupported(u, o, "Create_Ini", "off"); }},
    {.ini_key = "Bits_Per_Color", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Bits_Per_Color", "8"); }},
    {.ini_flag = "Dither", .kind = K::Flag, .set = [](U u, Options& o) { return unsupported(u, o, "Dither", "off"); }},
    {.ini_key = "Dither_Method", .kind = K::Value, .set = quiet},
    {.ini_flag = "Grayscale_Output", .kind = K::Flag,
     .set = [](U u, Options& o) { return unsupported(u, o, "Grayscale_Output", "off"); }},
    {.letters = "UF", .ini_flag = "Field_Render", .kind = K::Flag,
     .set = [](U u, Options& o) { return unsupported(u, o, "Field_Render", "off"); }},
    {.letters = "UO", .ini_flag = "Odd_Field", .kind = K::Flag, .set = quiet},
    {.ini_flag = "Clockless_Animation", .kind = K::Flag,
     .set = [](U u, Options& o) { return unsupported(u, o, "Clockless_Animation", "off"); }},
    {.letters = "RTR", .ini_flag = "Real_Time_Raytracing", .kind = K::Flag,
     .set = [](U u, Options& o) { return unsupported(u, o, "Real_Time_Raytracing", "off"); }},
    {.letters = "STP", .ini_key = "Frame_Step", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Frame_Step", "1"); }},
    {.letters = "HI", .ini_key = "Include_Header", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Include_Header", ""); }},
    {.ini_key = "Pre_Scene_Command", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Pre_Scene_Command", ""); }},
    {.ini_key = "Pre_Frame_Command", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Pre_Frame_Command", ""); }},
    {.ini_key = "Post_Frame_Command", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Post_Frame_Command", ""); }},
    {.ini_key = "Post_Scene_Command", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Post_Scene_Command", ""); }},
    {.ini_key = "User_Abort_Command", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "User_Abort_Command", ""); }},
    {.ini_key = "Fatal_Error_Command", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Fatal_Error_Command", ""); }},
    {.ini_key = "Histogram_Type", .kind = K::Value,
     .set = [](U u, Options& o) { return unsupported(u, o, "Histogram_Type", ""); }},
    {.ini_key = "Histogram_Name", .kind = K::Value, .set = quiet},
    {.ini_key = "Histogram_Grid_Size", .kind = K::Value, .set = quiet},
};

}  // namespace

std::span<const OptionSpec> frame_option_table() {
    return kFrameOptions;
}

}  // namespace wardray::app
