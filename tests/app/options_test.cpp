// Tests of the command line: POV-Ray switches, long options and usage errors.
#include "app/options.h"

#include <gtest/gtest.h>

namespace wardray::app {
namespace {

Options parse_ok(const std::vector<std::string>& args) {
    auto r = parse_command_line(args);
    EXPECT_TRUE(std::holds_alternative<Options>(r))
        << (std::holds_alternative<UsageError>(r) ? std::get<UsageError>(r).message : "");
    return std::holds_alternative<Options>(r) ? std::get<Options>(r) : Options{};
}

std::string parse_error(const std::vector<std::string>& args) {
    auto r = parse_command_line(args);
    EXPECT_TRUE(std::holds_alternative<UsageError>(r));
    return std::holds_alternative<UsageError>(r) ? std::get<UsageError>(r).message : "";
}

TEST(Options, DefaultsArePovRays) {
    const Options o = parse_ok({});
    EXPECT_TRUE(o.scene.empty());
    EXPECT_EQ(o.width, 320);
    EXPECT_EQ(o.height, 240);
    EXPECT_FALSE(o.output.has_value());
    EXPECT_FALSE(o.gi.has_value());
    EXPECT_TRUE(o.write_output);
}

TEST(Options, PovRaySwitches) {
    const Options o = parse_ok({"+Iscene.pov", "+Oout.exr", "+W640", "+H480", "+WT3", "+FH", "-D", "+V", "+A0.1",
                                "+L/tmp/inc"});
    EXPECT_EQ(o.scene, "scene.pov");
    EXPECT_EQ(*o.output, "out.exr");
    EXPECT_EQ(o.width, 640);
    EXPECT_EQ(o.height, 480);
    EXPECT_EQ(o.threads, 3);
    EXPECT_EQ(*o.format, render::ImageFormat::Hdr);
    EXPECT_TRUE(o.verbose);
    EXPECT_TRUE(o.antialias);
    EXPECT_DOUBLE_EQ(o.antialias_threshold, 0.1);
    ASSERT_EQ(o.library_paths.size(), 1u);
    EXPECT_EQ(o.library_paths[0], "/tmp/inc");
}

TEST(Options, AntialiasingSwitches) {
    const Options o = parse_ok({"+A0.2", "+R4", "+J0.5", "+AG2.2", "+AM1"});
    EXPECT_TRUE(o.antialias);
    EXPECT_DOUBLE_EQ(o.antialias_threshold, 0.2);
    EXPECT_EQ(o.antialias_depth, 4);
    EXPECT_DOUBLE_EQ(o.jitter, 0.5);
    EXPECT_DOUBLE_EQ(o.antialias_gamma, 2.2);
    EXPECT_DOUBLE_EQ(parse_ok({"-J"}).jitter, 0.0);
    EXPECT_DOUBLE_EQ(parse_ok({"+J"}).jitter, 1.0);
    EXPECT_NE(parse_error({"+R0"}).find("1..9"), std::string::npos);
    EXPECT_EQ(o.sampling_method, 1);
    EXPECT_EQ(parse_ok({"+AM2"}).sampling_method, 2);
    EXPECT_EQ(parse_ok({"+AM3"}).sampling_method, 2);  // POV-Ray 3.7 renders method 3 as 2
    EXPECT_NE(parse_error({"+AM4"}).find("sampling method"), std::string::npos);
    EXPECT_NE(parse_error({"+AG0"}).find("gamma"), std::string::npos);
}

TEST(Options, LowercaseSwitchesAndMinusForms) {
    const Options o = parse_ok({"scene.pov", "+w100", "+h50", "-A", "-F", "-V"});
    EXPECT_EQ(o.width, 100);
    EXPECT_EQ(o.height, 50);
    EXPECT_FALSE(o.antialias);
    EXPECT_FALSE(o.write_output);
    EXPECT_FALSE(o.verbose);
}

TEST(Options, LongOptions) {
    const Options o = parse_ok({"scene.pov", "-o", "x.png", "--threads", "2", "--gi=reference", "--stats",
                                "s.json", "--check"});
    EXPECT_EQ(*o.output, "x.png");
    EXPECT_EQ(o.threads, 2);
    EXPECT_EQ(*o.gi, lighting::GiMode::Reference);
    EXPECT_EQ(*o.stats, "s.json");
    EXPECT_TRUE(o.check_only);
    EXPECT_EQ(*parse_ok({"--gi", "off"}).gi, lighting::GiMode::Off);
    EXPECT_EQ(*parse_ok({"--output=y.hdr"}).output, "y.hdr");
}

TEST(Options, DeclareDefinesFloats) {
    const Options o = parse_ok({"Declare=Count=12", "declare=Half=0.5"});
    ASSERT_EQ(o.declares.size(), 2u);
    EXPECT_EQ(o.declares[0].first, "Count");
    EXPECT_DOUBLE_EQ(o.declares[0].second, 12.0);
    EXPECT_EQ(o.declares[1].first, "Half");
    EXPECT_DOUBLE_EQ(o.declares[1].second, 0.5);
}

TEST(Options, UsageErrorsNameTheProblem) {
    EXPECT_NE(parse_error({"+W0"}).find("+W0"), std::string::npos);
    EXPECT_NE(parse_error({"+Wabc"}).find("size"), std::string::npos);
    EXPECT_NE(parse_error({"+W100000"}).find("65536"), std::string::npos);
    EXPECT_NE(parse_error({"+ZZ9"}).find("unknown switch"), std::string::npos);
    EXPECT_NE(parse_error({"--frobnicate"}).find("--frobnicate"), std::string::npos);
    EXPECT_NE(parse_error({"--gi=fast"}).find("cache, reference or off"), std::string::npos);
    EXPECT_NE(parse_error({"--threads", "0"}).find("--threads"), std::string::npos);
    EXPECT_NE(parse_error({"-o"}).find("file name"), std::string::npos);
    EXPECT_NE(parse_error({"Declare=X"}).find("Declare=NAME=NUMBER"), std::string::npos);
    EXPECT_NE(parse_error({"+FT"}).find("+FN"), std::string::npos);
    EXPECT_NE(parse_error({"a.pov", "b.pov"}).find("more than one scene"), std::string::npos);
}

}  // namespace
}  // namespace wardray::app

namespace wardray::app {
namespace {

TEST(Options, RadiositySwitches) {
    const Options o = parse_ok({"+RFI", "+RFO", "+RFcache.rca", "--gi=reference", "--gi-rays", "64",
                                "--gi-light-picks", "0", "--gi-gradients=off", "--no-pretrace", "--aov", "irradiance", "irr.exr", "--aov",
                                "records", "rec.png"});
    EXPECT_TRUE(o.radiosity_load);
    EXPECT_TRUE(o.radiosity_save);
    ASSERT_TRUE(o.radiosity_file);
    EXPECT_EQ(o.radiosity_file->string(), "cache.rca");
    EXPECT_EQ(o.gi, lighting::GiMode::Reference);
    EXPECT_EQ(o.gi_rays, 64);
    EXPECT_EQ(o.gi_light_picks, 0);
    EXPECT_EQ(parse_ok({}).gi_light_picks, 1);
    EXPECT_TRUE(parse_ok({}).gi_guide);
    EXPECT_FALSE(parse_ok({"--gi-guide=off"}).gi_guide);
    EXPECT_NE(parse_error({"--gi-guide=maybe"}).find("--gi-guide"), std::string::npos);
    EXPECT_TRUE(parse_ok({}).gi_fine_area_lights);
    EXPECT_FALSE(parse_ok({"--gi-area-lights=grid"}).gi_fine_area_lights);
    EXPECT_TRUE(parse_ok({"--gi-area-lights=grid", "--gi-area-lights=fine"}).gi_fine_area_lights);
    EXPECT_NE(parse_error({"--gi-area-lights=coarse"}).find("--gi-area-lights"), std::string::npos);
    EXPECT_FALSE(parse_ok({}).gi_path_seed);
    EXPECT_EQ(parse_ok({"--gi-path-seed", "7"}).gi_path_seed, std::optional<std::uint64_t>(7));
    EXPECT_EQ(parse_ok({"--gi-path-seed", "7"}).seed, 0u);
    EXPECT_NE(parse_error({"--gi-path-seed", "-1"}).find("--gi-path-seed"), std::string::npos);
    EXPECT_FALSE(o.gi_gradients);
    EXPECT_FALSE(o.pretrace);
    ASSERT_TRUE(o.aov_irradiance && o.aov_records);
    EXPECT_EQ(o.aov_irradiance->string(), "irr.exr");
    EXPECT_EQ(o.aov_records->string(), "rec.png");
    EXPECT_FALSE(parse_ok({"+RFI", "-RFI"}).radiosity_load);
    EXPECT_NE(parse_error({"--gi-rays", "0"}).find("--gi-rays"), std::string::npos);
    EXPECT_NE(parse_error({"--gi-light-picks", "-1"}).find("--gi-light-picks"), std::string::npos);
    EXPECT_NE(parse_error({"--aov", "normals", "n.png"}).find("--aov"), std::string::npos);
    EXPECT_NE(parse_error({"--gi-gradients=maybe"}).find("--gi-gradients"), std::string::npos);
}

TEST(Options, RecordRadiusLimitSwitches) {
    const Options defaults = parse_ok({});
    EXPECT_TRUE(defaults.gi_gradient_cap);
    EXPECT_TRUE(defaults.gi_neighbour_clamp);
    const Options off = parse_ok({"--gi-gradient-cap=off", "--gi-neighbour-clamp=off"});
    EXPECT_FALSE(off.gi_gradient_cap);
    EXPECT_FALSE(off.gi_neighbour_clamp);
    const Options on = parse_ok({"--gi-gradient-cap=off", "--gi-gradient-cap=on", "--gi-neighbour-clamp=on"});
    EXPECT_TRUE(on.gi_gradient_cap);
    EXPECT_TRUE(on.gi_neighbour_clamp);
    EXPECT_NE(parse_error({"--gi-gradient-cap=no"}).find("--gi-gradient-cap"), std::string::npos);
    EXPECT_NE(parse_error({"--gi-neighbour-clamp=1"}).find("--gi-neighbour-clamp"), std::string::npos);
}

TEST(Options, RecordSpacingSwitch) {
    EXPECT_TRUE(parse_ok({}).gi_hessian_spacing);
    EXPECT_FALSE(parse_ok({"--gi-spacing=harmonic"}).gi_hessian_spacing);
    EXPECT_TRUE(parse_ok({"--gi-spacing=harmonic", "--gi-spacing=hessian"}).gi_hessian_spacing);
    EXPECT_NE(parse_error({"--gi-spacing=ward"}).find("--gi-spacing"), std::string::npos);
}

TEST(Options, LookupSamplingSwitch) {
    EXPECT_EQ(parse_ok({}).gi_lookup_sampling, 4);
    EXPECT_EQ(parse_ok({"--gi-lookup-sampling", "1"}).gi_lookup_sampling, 1);
    EXPECT_EQ(parse_ok({"--gi-lookup-sampling", "8"}).gi_lookup_sampling, 8);
    EXPECT_EQ(parse_ok({"--gi-lookup-sampling", "64"}).gi_lookup_sampling, 64);
    for (const char* bad : {"0", "65", "two"})
        EXPECT_NE(parse_error({"--gi-lookup-sampling", bad}).find("--gi-lookup-sampling"), std::string::npos) << bad;
}

TEST(Options, AdaptiveGatherSwitch) {
    EXPECT_FALSE(parse_ok({}).gi_adaptive);
    EXPECT_FALSE(parse_ok({"--gi-adaptive=off"}).gi_adaptive);
    EXPECT_TRUE(parse_ok({"--gi-adaptive=on"}).gi_adaptive);
    EXPECT_TRUE(parse_ok({"--gi-adaptive=off", "--gi-adaptive=on"}).gi_adaptive);
    EXPECT_NE(parse_error({"--gi-adaptive=yes"}).find("--gi-adaptive"), std::string::npos);
    EXPECT_TRUE(parse_ok({}).gi_geometry_floor);
    EXPECT_FALSE(parse_ok({"--gi-reuse-floor=screen"}).gi_geometry_floor);
    EXPECT_TRUE(parse_ok({"--gi-reuse-floor=screen", "--gi-reuse-floor=geometry"}).gi_geometry_floor);
    EXPECT_NE(parse_error({"--gi-reuse-floor=on"}).find("--gi-reuse-floor"), std::string::npos);
}

TEST(Options, PretraceBoundSwitch) {
    EXPECT_FALSE(parse_ok({}).gi_pov_pretrace_bound);
    EXPECT_TRUE(parse_ok({"--gi-pretrace-bound=pov"}).gi_pov_pretrace_bound);
    EXPECT_FALSE(parse_ok({"--gi-pretrace-bound=pov", "--gi-pretrace-bound=final"}).gi_pov_pretrace_bound);
    EXPECT_NE(parse_error({"--gi-pretrace-bound=on"}).find("--gi-pretrace-bound"), std::string::npos);
}

TEST(Options, SeedTakesAny64BitNumber) {
    EXPECT_EQ(parse_ok({}).seed, 0u);
    EXPECT_EQ(parse_ok({"--seed", "7"}).seed, 7u);
    EXPECT_EQ(parse_ok({"--seed", "18446744073709551615"}).seed, 18446744073709551615ull);
    for (const char* bad : {"-1", "18446744073709551616", "1.5", "seven", ""})
        EXPECT_NE(parse_error({"--seed", bad}).find("--seed"), std::string::npos) << bad;
}

}  // namespace
}  // namespace wardray::app
