// The GIF decoder against hand-made files (literal codes, clear codes, a code defined by its own use, interlaced
// rows, extensions and a local colour table) and POV-Ray's own POT file.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include "render/film.h"
#include "render/gif_reader.h"

namespace wardray::render {
namespace {

namespace fs = std::filesystem;

// Codes of the given bit sizes packed least significant bit first, split into sub-blocks.
std::vector<std::uint8_t> pack(const std::vector<std::pair<int, int>>& codes) {
    std::vector<std::uint8_t> bytes;
    std::size_t bit = 0;
    for (const auto& [code, size] : codes)
        for (int i = 0; i < size; ++i, ++bit) {
            if (bit / 8 >= bytes.size()) bytes.push_back(0);
            bytes[bit / 8] |= static_cast<std::uint8_t>(((code >> i) & 1) << (bit % 8));
        }
    std::vector<std::uint8_t> blocks{static_cast<std::uint8_t>(bytes.size())};
    blocks.insert(blocks.end(), bytes.begin(), bytes.end());
    blocks.push_back(0);
    return blocks;
}

// Appends the image data (`codes` packed), the trailer, and writes `f` to the temporary folder as `name`.
fs::path finish_gif(std::vector<std::uint8_t>& f, const std::vector<std::pair<int, int>>& codes,
                    const std::string& name) {
    const std::vector<std::uint8_t> data = pack(codes);
    f.insert(f.end(), data.begin(), data.end());
    f.push_back(';');
    const fs::path path = fs::temp_directory_path() / name;
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(f.data()), static_cast<std::streamsize>(f.size()));
    return path;
}

// A GIF89a of w × h with a 4-entry global table, a comment extension, and the image (local table if asked).
fs::path write_gif(const std::string& name, int w, int h, const std::vector<std::pair<int, int>>& codes,
                   bool interlaced = false, bool local_table = false) {
    std::vector<std::uint8_t> f = {'G', 'I', 'F', '8', '9', 'a', static_cast<std::uint8_t>(w), 0,
                                   static_cast<std::uint8_t>(h), 0, 0x81, 0, 0};
    for (int i = 0; i < 12; ++i) f.push_back(static_cast<std::uint8_t>(i * 20));
    for (int b : {0x21, 0xFE, 3, 0x68, 0x69, 0x21, 0}) f.push_back(static_cast<std::uint8_t>(b));  // a comment: "hi!"
    std::uint8_t flags = (interlaced ? 0x40 : 0) | (local_table ? 0x81 : 0);
    for (std::uint8_t b : {std::uint8_t(','), std::uint8_t(0), std::uint8_t(0), std::uint8_t(0), std::uint8_t(0),
                           static_cast<std::uint8_t>(w), std::uint8_t(0), static_cast<std::uint8_t>(h),
                           std::uint8_t(0), flags})
        f.push_back(b);
    if (local_table)
        for (int i = 0; i < 12; ++i) f.push_back(7);
    f.push_back(2);  // minimum code size: codes 0..3, clear 4, end 5
    return finish_gif(f, codes, name);
}

TEST(GifReader, DecodesLiteralsClearCodesAndTheCodeBeingDefined) {
    // Clear, 1, 2 (defines 6 = "1 2"), 6 (defines 7, so codes grow to 4 bits), clear (back to 3 bits), 3, then 6
    // before it is defined ("3 3"), end: 1 2 1 2 3 3 3.
    const fs::path path = write_gif("wardray_gif_test1.gif", 7, 1,
                                    {{4, 3}, {1, 3}, {2, 3}, {6, 3}, {4, 4}, {3, 3}, {6, 3}, {5, 3}});
    std::string error;
    const auto gif = read_gif_indices(path, error);
    ASSERT_TRUE(gif) << error;
    EXPECT_EQ(gif->width, 7);
    EXPECT_EQ(gif->height, 1);
    EXPECT_EQ(gif->index, (std::vector<std::uint8_t>{1, 2, 1, 2, 3, 3, 3}));
    fs::remove(path);
}

TEST(GifReader, PutsInterlacedRowsInPlaceAndSkipsALocalTable) {
    // Ten rows of one pixel, row r stored in interlace order with index r % 4: passes 0 8, 4, 2 6, 1 3 5 7 9.
    const int order[10] = {0, 8, 4, 2, 6, 1, 3, 5, 7, 9};
    std::vector<std::pair<int, int>> codes;
    for (int r : order) {
        codes.push_back({4, 3});
        codes.push_back({r % 4, 3});
    }
    codes.push_back({5, 3});
    const fs::path path = write_gif("wardray_gif_test2.gif", 1, 10, codes, true, true);
    std::string error;
    const auto gif = read_gif_indices(path, error);
    ASSERT_TRUE(gif) << error;
    ASSERT_EQ(gif->index.size(), 10u);
    for (int r = 0; r < 10; ++r) EXPECT_EQ(gif->index[static_cast<std::size_t>(r)], r % 4) << r;
    fs::remove(path);
}

TEST(GifReader, ReadsPovRaysPotFileAndRefusesOtherFiles) {
    std::string error;
    const auto pot = read_gif_indices("/usr/share/povray-3.7/include/mtmand.pot", error);
    ASSERT_TRUE(pot) << error;
    EXPECT_EQ(pot->width, 320);
    EXPECT_EQ(pot->height, 120);
    EXPECT_FALSE(read_gif_indices("/usr/share/povray-3.7/include/colors.inc", error));
    EXPECT_FALSE(error.empty());
}

// A GIF89a on a 5 x 4 screen with a 4-entry global table, a graphic control extension naming `transparent`
// (none when negative), and a 3 x 2 image at (1, 1) with a local table, holding `indices` (each after a clear code).
fs::path write_placed_gif(const std::string& name, int transparent, const std::vector<int>& indices) {
    std::vector<std::uint8_t> f = {'G', 'I', 'F', '8', '9', 'a', 5, 0, 4, 0, 0x81, 0, 0};
    for (int i = 0; i < 12; ++i) f.push_back(static_cast<std::uint8_t>(i * 20));
    if (transparent >= 0)
        for (int b : {0x21, 0xF9, 4, 1, 0, 0, transparent, 0}) f.push_back(static_cast<std::uint8_t>(b));
    for (int b : {int(','), 1, 0, 1, 0, 3, 0, 2, 0, 0x81}) f.push_back(static_cast<std::uint8_t>(b));
    for (int i = 0; i < 12; ++i) f.push_back(static_cast<std::uint8_t>(255 - i * 7));
    f.push_back(2);
    std::vector<std::pair<int, int>> codes;
    for (int i : indices) {
        codes.push_back({4, 3});
        codes.push_back({i, 3});
    }
    codes.push_back({5, 3});
    return finish_gif(f, codes, name);
}

// Read without OpenImageIO, a GIF image map gives exactly what OpenImageIO gives: the same colours, alpha and flags.
void expect_gif_as_oiio_reads_it(const fs::path& path) {
    std::string error;
    bool stored = false, alpha = false;
    std::vector<float> alpha_values;
    const auto ours = read_image(path, error, &stored, &alpha, nullptr, nullptr, &alpha_values);
    ASSERT_TRUE(ours) << error;
    bool their_stored = false, their_alpha = false;
    std::vector<float> their_alpha_values;
    const auto theirs = read_image_with_oiio(path, error, &their_stored, &their_alpha, nullptr, nullptr,
                                             &their_alpha_values);
    ASSERT_TRUE(theirs) << error;
    EXPECT_EQ(stored, their_stored);
    EXPECT_EQ(alpha, their_alpha);
    EXPECT_EQ(alpha_values, their_alpha_values);
    ASSERT_EQ(ours->width(), theirs->width());
    ASSERT_EQ(ours->height(), theirs->height());
    EXPECT_EQ(ours->data(), theirs->data()) << path;
}

TEST(GifReader, ImageMapColoursAndTransparencyAreOpenImageIOs) {
    const std::vector<int> indices = {0, 1, 2, 3, 1, 0};
    expect_gif_as_oiio_reads_it(write_placed_gif("wardray_gif_test3.gif", 2, indices));
    expect_gif_as_oiio_reads_it(write_placed_gif("wardray_gif_test4.gif", -1, indices));
    expect_gif_as_oiio_reads_it("/usr/share/povray-3.7/include/mtmand.pot");
    int w = 0, h = 0;
    std::vector<float> rgb;
    ASSERT_TRUE(read_gif_rgb(fs::temp_directory_path() / "wardray_gif_test3.gif", w, h, rgb));
    EXPECT_EQ(w, 5);
    EXPECT_EQ(h, 4);
    // The local table's entry 1 at (2, 1); index 2 (transparent) at (3, 1) and the screen around the image black.
    EXPECT_EQ(rgb[(1 * 5 + 2) * 3], 234.0f * (1.0f / 255.0f));
    for (const int at : {0, 1 * 5 + 3, 3 * 5 + 4}) EXPECT_EQ(rgb[at * 3] + rgb[at * 3 + 1] + rgb[at * 3 + 2], 0.0f) << at;
    EXPECT_FALSE(read_gif_rgb("/usr/share/povray-3.7/include/colors.inc", w, h, rgb));
    fs::remove(fs::temp_directory_path() / "wardray_gif_test3.gif");
    fs::remove(fs::temp_directory_path() / "wardray_gif_test4.gif");
}

}  // namespace
}  // namespace wardray::render
