// A GIF image map as POV-Ray 3.7 reads it: a colour-mapped image whose transparent entry (its graphic control
// extension's) transmits fully and keeps its palette colour, the other entries opaque; `transmit N` per entry.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/run.h"
#include "texture/pigment.h"

namespace wardray::app {
namespace {

namespace fs = std::filesystem;

// A 3 x 1 GIF89a of palette indices 0, 1, 2 with a 4-entry table (red, green, blue, white); `transparent` names the
// transparent entry (none when negative). Each index follows a clear code, so every code is 3 bits wide.
void write_gif(const fs::path& path, int transparent) {
    std::vector<std::uint8_t> f = {'G', 'I', 'F', '8', '9', 'a', 3, 0, 1, 0, 0x81, 0, 0};
    for (int b : {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255}) f.push_back(static_cast<std::uint8_t>(b));
    if (transparent >= 0)
        for (int b : {0x21, 0xF9, 4, 1, 0, 0, transparent, 0}) f.push_back(static_cast<std::uint8_t>(b));
    for (int b : {int(','), 0, 0, 0, 0, 3, 0, 1, 0, 0}) f.push_back(static_cast<std::uint8_t>(b));
    f.push_back(2);  // minimum code size 2: literals 0-3, clear 4, end 5
    const int codes[] = {4, 0, 4, 1, 4, 2, 5};
    std::vector<std::uint8_t> bytes;
    std::size_t bit = 0;
    for (int code : codes)
        for (int i = 0; i < 3; ++i, ++bit) {
            if (bit / 8 >= bytes.size()) bytes.push_back(0);
            bytes[bit / 8] |= static_cast<std::uint8_t>(((code >> i) & 1) << (bit % 8));
        }
    f.push_back(static_cast<std::uint8_t>(bytes.size()));
    f.insert(f.end(), bytes.begin(), bytes.end());
    f.push_back(0);
    f.push_back(';');
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(f.data()),
                                                static_cast<std::streamsize>(f.size()));
}

class GifImageMap : public ::testing::Test {
protected:
    void SetUp() override {
        // A folder per test: ctest runs the tests of this file side by side, and each writes its own t.gif.
        m_dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "gif_image_map" /
                ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::create_directories(m_dir);
    }
    // The image map's pigment of `image_map { gif "t.gif" ITEMS }` with the GIF written as write_gif says.
    scene::Pigment pigment(int transparent, const std::string& items = "") {
        write_gif(m_dir / "t.gif", transparent);
        std::ofstream(m_dir / "s.pov") << "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                                       << "plane { z, 0 pigment { image_map { gif \"t.gif\" " << items << " } } }\n";
        Options o;
        o.scene = m_dir / "s.pov";
        o.check_only = true;
        const std::optional<LoadedScene> loaded = load_scene(o);
        EXPECT_TRUE(loaded.has_value());
        if (!loaded) return {};
        for (const Diagnostic& w : loaded->scene.warnings) ADD_FAILURE() << w.message;
        return loaded->scene.objects.at(0).texture->pigment;
    }
    // The texel of column `x` (of 3), at the image's middle row.
    static Color texel(const scene::Pigment& p, int x) {
        return texture::evaluate_pigment(p, {(x + 0.5) / 3.0, 0.5, 0.0}, 2);
    }
    fs::path m_dir;
};

TEST_F(GifImageMap, TheTransparentEntryTransmitsAndKeepsItsColour) {
    const scene::Pigment p = pigment(1);
    EXPECT_NEAR(texel(p, 0).r, 1.0, 1e-6);
    EXPECT_NEAR(texel(p, 0).transmit, 0.0, 1e-6);
    EXPECT_NEAR(texel(p, 1).transmit, 1.0, 1e-6);
    EXPECT_NEAR(texel(p, 1).g, 1.0, 1e-6);  // its palette's green, not black
    EXPECT_NEAR(texel(p, 1).r, 0.0, 1e-6);
    EXPECT_NEAR(texel(p, 2).b, 1.0, 1e-6);
    EXPECT_NEAR(texel(p, 2).transmit, 0.0, 1e-6);
}

TEST_F(GifImageMap, WithoutATransparentEntryItIsOpaqueAndTransmitSetsOneEntry) {
    const scene::Pigment opaque = pigment(-1);
    for (int x = 0; x < 3; ++x) EXPECT_NEAR(texel(opaque, x).transmit, 0.0, 1e-6) << x;
    const scene::Pigment one = pigment(-1, "transmit 2, 0.5");
    EXPECT_NEAR(texel(one, 0).transmit, 0.0, 1e-6);
    EXPECT_NEAR(texel(one, 2).transmit, 0.5, 1e-6);
}

}  // namespace
}  // namespace wardray::app
