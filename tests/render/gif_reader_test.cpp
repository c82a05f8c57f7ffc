// The GIF decoder against hand-made files (literal codes, clear codes, a code defined by its own use, interlaced
// rows, extensions and a local colour table) and POV-Ray's own POT file.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

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
    const std::vector<std::uint8_t> data = pack(codes);
    f.insert(f.end(), data.begin(), data.end());
    f.push_back(';');
    const fs::path path = fs::temp_directory_path() / name;
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(f.data()), static_cast<std::streamsize>(f.size()));
    return path;
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

}  // namespace
}  // namespace wardray::render
