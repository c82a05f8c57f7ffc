// Tests of the libpng and libjpeg readers: every opaque kind of PNG, and grey and colour JPEGs, give exactly
// what OpenImageIO gives, and files they leave alone (an alpha channel) still read through OpenImageIO.
#include "render/film.h"
#include "render/height_image.h"
#include "render/image_header.h"
#include "render/image_header.h"
#include "render/jpeg_reader.h"
#include "render/png_reader.h"

#include <jpeglib.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace wardray::render {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

std::uint32_t crc32(const Bytes& data, std::size_t from) {
    std::uint32_t c = 0xffffffffu;
    for (std::size_t i = from; i < data.size(); ++i) {
        c ^= data[i];
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

void put32(Bytes& b, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<unsigned char>(v >> s));
}

void chunk(Bytes& png, const char* type, const Bytes& data) {
    put32(png, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = png.size();
    png.insert(png.end(), type, type + 4);
    png.insert(png.end(), data.begin(), data.end());
    put32(png, crc32(png, start));
}

/// A PNG of `rows` (each with its filter byte 0 already in front), deflated as stored blocks.
Bytes make_png(int width, int height, int depth, int color_type, const Bytes& rows, const Bytes& palette = {},
               const Bytes& trns = {}) {
    Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    Bytes ihdr;
    put32(ihdr, width);
    put32(ihdr, height);
    ihdr.insert(ihdr.end(), {static_cast<unsigned char>(depth), static_cast<unsigned char>(color_type), 0, 0, 0});
    chunk(png, "IHDR", ihdr);
    if (!palette.empty()) chunk(png, "PLTE", palette);
    if (!trns.empty()) chunk(png, "tRNS", trns);
    Bytes z = {0x78, 0x01, 0x01, static_cast<unsigned char>(rows.size() & 0xff),
               static_cast<unsigned char>(rows.size() >> 8), static_cast<unsigned char>(~rows.size() & 0xff),
               static_cast<unsigned char>((~rows.size() >> 8) & 0xff)};
    z.insert(z.end(), rows.begin(), rows.end());
    std::uint32_t a = 1, b = 0;
    for (unsigned char c : rows) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    put32(z, (b << 16) | a);
    chunk(png, "IDAT", z);
    chunk(png, "IEND", {});
    return png;
}

/// Rows of `width` samples of `bytes_per_pixel` bytes, each byte a fixed pseudo-random value.
Bytes rows_of(int width, int height, int bytes_per_row) {
    Bytes rows;
    std::uint32_t state = 12345;
    for (int y = 0; y < height; ++y) {
        rows.push_back(0);
        for (int i = 0; i < bytes_per_row; ++i) {
            state = state * 1103515245u + 12345u;
            rows.push_back(static_cast<unsigned char>(state >> 16));
        }
    }
    (void)width;
    return rows;
}

fs::path write(const std::string& name, const Bytes& png) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "png_reader_test";
    fs::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), png.size());
    return dir / name;
}

void expect_same_as_oiio(const fs::path& p, bool jpeg = false) {
    std::string error;
    bool stored = false, alpha = true;
    int w = 0, h = 0;
    std::vector<float> rgb;
    ASSERT_TRUE(jpeg ? read_jpeg_rgb(p, w, h, rgb) : read_png_rgb(p, w, h, rgb)) << p;
    const auto ours = read_image(p, error, &stored, &alpha);
    const auto theirs = read_image_with_oiio(p, error);
    ASSERT_TRUE(ours && theirs) << error;
    EXPECT_TRUE(stored);
    EXPECT_FALSE(alpha);
    const auto linear = read_image(p, error);
    ASSERT_TRUE(linear);
    ASSERT_EQ(linear->width(), theirs->width());
    ASSERT_EQ(linear->height(), theirs->height());
    for (int y = 0; y < theirs->height(); ++y)
        for (int x = 0; x < theirs->width(); ++x) {
            const Vec3 a = linear->pixel(x, y), b = theirs->pixel(x, y);
            ASSERT_EQ(a.x, b.x) << p << " at " << x << "," << y;
            ASSERT_EQ(a.y, b.y);
            ASSERT_EQ(a.z, b.z);
        }
}

TEST(PngReader, OpaqueKindsReadAsOpenImageIOReadsThem) {
    expect_same_as_oiio(write("rgb8.png", make_png(7, 5, 8, 2, rows_of(7, 5, 21))));
    expect_same_as_oiio(write("rgb16.png", make_png(6, 4, 16, 2, rows_of(6, 4, 36))));
    expect_same_as_oiio(write("gray8.png", make_png(9, 3, 8, 0, rows_of(9, 3, 9))));
    expect_same_as_oiio(write("gray16.png", make_png(5, 3, 16, 0, rows_of(5, 3, 10))));
    expect_same_as_oiio(write("gray1.png", make_png(16, 2, 1, 0, rows_of(16, 2, 2))));
    expect_same_as_oiio(write("gray4.png", make_png(6, 2, 4, 0, rows_of(6, 2, 3))));
    Bytes palette;
    for (int i = 0; i < 16 * 3; ++i) palette.push_back(static_cast<unsigned char>(i * 5 + 3));
    Bytes indices;  // 4-bit indices below 16
    for (int y = 0; y < 3; ++y) {
        indices.push_back(0);
        for (int i = 0; i < 4; ++i) indices.push_back(static_cast<unsigned char>(((y + i) % 16) << 4 | (i * 3 % 16)));
    }
    expect_same_as_oiio(write("palette4.png", make_png(8, 3, 4, 3, indices, palette)));
    // A known value: the stored byte over 255, and sRGB-decoded by default.
    Bytes one = {0, 255, 128, 0};
    const fs::path p = write("one.png", make_png(1, 1, 8, 2, one));
    std::string error;
    bool stored = false;
    const auto raw = read_image(p, error, &stored);
    ASSERT_TRUE(raw);
    EXPECT_EQ(raw->pixel(0, 0).x, 1.0);
    EXPECT_EQ(raw->pixel(0, 0).y, static_cast<double>(128.0f * (1.0f / 255.0f)));
    EXPECT_NEAR(read_image(p, error)->pixel(0, 0).y, 0.2158605, 1e-6);
}

TEST(PngReader, AlphaAndOtherFilesAreLeftToOpenImageIO) {
    const fs::path p = write("rgba8.png", make_png(3, 2, 8, 6, rows_of(3, 2, 12)));
    int w = 0, h = 0;
    std::vector<float> rgb;
    EXPECT_FALSE(read_png_rgb(p, w, h, rgb));
    std::string error;
    bool alpha = false;
    ASSERT_TRUE(read_image(p, error, nullptr, &alpha)) << error;
    EXPECT_TRUE(alpha);
    const fs::path text = write("not.png", Bytes{'h', 'e', 'l', 'l', 'o', '!', '!', '!', '!'});
    EXPECT_FALSE(read_png_rgb(text, w, h, rgb));
    EXPECT_FALSE(read_image(text, error).has_value());
}

/// A 6x3 palette PNG of 8-bit indices into 16 entries, with a tRNS chunk for the first `trns_entries` of them.
Bytes palette_with_trns(int trns_entries) {
    Bytes palette, trns;
    for (int i = 0; i < 16 * 3; ++i) palette.push_back(static_cast<unsigned char>(i * 5 + 3));
    for (int i = 0; i < trns_entries; ++i) trns.push_back(static_cast<unsigned char>(255 - i * 37 % 256));
    Bytes indices;
    for (int y = 0; y < 3; ++y) {
        indices.push_back(0);
        for (int x = 0; x < 6; ++x) indices.push_back(static_cast<unsigned char>((x * 5 + y * 3) % 16));
    }
    return make_png(6, 3, 8, 3, indices, palette, trns);
}

// PNGs with an alpha channel, and palettes with a tRNS chunk (POV-Ray's bumpmap_.png): the colours, straight, and
// the alpha exactly as OpenImageIO reads them.
TEST(PngReader, AlphaKindsReadAsOpenImageIOReadsThem) {
    for (const auto& [name, png] : {std::pair{"palette-trns.png", palette_with_trns(16)},
                                    std::pair{"palette-short-trns.png", palette_with_trns(5)},
                                    std::pair{"rgba8.png", make_png(3, 2, 8, 6, rows_of(3, 2, 12))},
                                    std::pair{"rgba16.png", make_png(5, 3, 16, 6, rows_of(5, 3, 40))},
                                    std::pair{"grey-alpha8.png", make_png(4, 3, 8, 4, rows_of(4, 3, 8))},
                                    std::pair{"grey-alpha16.png", make_png(3, 3, 16, 4, rows_of(3, 3, 12))}}) {
        const fs::path p = write(name, png);
        int w = 0, h = 0;
        std::vector<float> rgb, alpha;
        ASSERT_TRUE(read_png_rgba(p, w, h, rgb, alpha)) << name;
        std::string error;
        bool stored = false, has_alpha = false, their_stored = false, their_alpha = false;
        std::vector<float> alpha_values, their_alpha_values;
        const auto ours = read_image(p, error, &stored, &has_alpha, nullptr, nullptr, &alpha_values);
        const auto theirs = read_image_with_oiio(p, error, &their_stored, &their_alpha, nullptr, nullptr,
                                                 &their_alpha_values);
        ASSERT_TRUE(ours && theirs) << error;
        EXPECT_EQ(stored, their_stored);
        EXPECT_TRUE(has_alpha);
        EXPECT_EQ(has_alpha, their_alpha);
        EXPECT_EQ(alpha_values, their_alpha_values) << name;
        EXPECT_EQ(alpha_values, alpha);
        EXPECT_EQ(ours->data(), theirs->data()) << name;
        EXPECT_EQ(ours->data(), rgb);
        const auto linear = read_image(p, error), their_linear = read_image_with_oiio(p, error);
        ASSERT_TRUE(linear && their_linear);
        EXPECT_EQ(linear->data(), their_linear->data()) << name;
    }
    int w = 0, h = 0;
    std::vector<float> rgb, alpha;
    EXPECT_FALSE(read_png_rgba(write("rgb8-no-alpha.png", make_png(2, 2, 8, 2, rows_of(2, 2, 6))), w, h, rgb, alpha));
}

/// A JPEG of pseudo-random smooth content, written by libjpeg at its defaults (4:2:0 for colour).
fs::path write_jpeg(const std::string& name, int width, int height, int components) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "png_reader_test";
    fs::create_directories(dir);
    const fs::path p = dir / name;
    std::FILE* f = std::fopen(p.c_str(), "wb");
    jpeg_compress_struct info;
    jpeg_error_mgr errors;
    info.err = jpeg_std_error(&errors);
    jpeg_create_compress(&info);
    jpeg_stdio_dest(&info, f);
    info.image_width = width;
    info.image_height = height;
    info.input_components = components;
    info.in_color_space = components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, 80, TRUE);
    jpeg_start_compress(&info, TRUE);
    std::vector<unsigned char> row(static_cast<std::size_t>(width) * components);
    for (int y = 0; y < height; ++y) {
        for (int i = 0; i < width * components; ++i) row[i] = static_cast<unsigned char>((i * 7 + y * 13) ^ (i * y));
        JSAMPROW rows[1] = {row.data()};
        jpeg_write_scanlines(&info, rows, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    std::fclose(f);
    return p;
}

TEST(JpegReader, GreyAndColourReadAsOpenImageIOReadsThem) {
    expect_same_as_oiio(write_jpeg("colour.jpg", 37, 21, 3), true);
    expect_same_as_oiio(write_jpeg("grey.jpg", 19, 11, 1), true);
    int w = 0, h = 0;
    std::vector<float> rgb;
    EXPECT_FALSE(read_jpeg_rgb(write("rgb8-as-jpeg.png", make_png(2, 2, 8, 2, rows_of(2, 2, 6))), w, h, rgb));
}

// Height fields ask whether the file is grey or 16-bit: a JPEG answers as OpenImageIO answers, without loading it.
TEST(JpegReader, HeightFieldReadsAnswerGreyAsOpenImageIO) {
    for (const int components : {1, 3}) {
        const fs::path p = write_jpeg("height" + std::to_string(components) + ".jpg", 23, 13, components);
        std::string error;
        bool stored = false, alpha = true, grey = false, bits16 = true;
        const auto ours = read_image(p, error, &stored, &alpha, &grey, &bits16);
        bool their_stored = false, their_alpha = true, their_grey = false, their_bits16 = true;
        const auto theirs = read_image_with_oiio(p, error, &their_stored, &their_alpha, &their_grey, &their_bits16);
        ASSERT_TRUE(ours && theirs) << error;
        EXPECT_EQ(stored, their_stored);
        EXPECT_EQ(alpha, their_alpha);
        EXPECT_EQ(grey, their_grey);
        EXPECT_EQ(grey, components == 1);
        EXPECT_EQ(bits16, their_bits16);
        EXPECT_EQ(ours->data(), theirs->data());
    }
}

// POV-Ray 3.7 stores an 8-bit grey PNG texel as its colour table's grey in float times 255, cut, so some levels
// come out one lower: measured with trace() on a height field of every level, levels 3, 5 and 127 stand as high as
// 2, 4 and 126, 199 and 200 as 198 and 199, while 4 and 128 keep their own height. Low-depth grey goes the same way.
TEST(PngReader, GreyHeightFieldLevelsAsPovRayStoresThem) {
    Bytes rows;
    for (int y = 0; y < 16; ++y) {
        rows.push_back(0);
        for (int x = 0; x < 16; ++x) rows.push_back(static_cast<unsigned char>(x + 16 * y));
    }
    std::string error, unsupported;
    const auto grid = read_height_grid(write("levels8.png", make_png(16, 16, 8, 0, rows)), error, unsupported);
    ASSERT_TRUE(grid) << error;
    // Image row y is grid row 15 - y.
    const auto level = [&](int v) { return grid->at(v % 16, 15 - v / 16); };
    EXPECT_EQ(level(3), level(2));
    EXPECT_EQ(level(5), level(4));
    EXPECT_EQ(level(127), level(126));
    EXPECT_NEAR(level(199), 198 * 257, 1);
    EXPECT_NEAR(level(200), 199 * 257, 1);
    EXPECT_GT(level(4), level(3));
    EXPECT_GT(level(128), level(127));
    EXPECT_NEAR(level(4), 4 * 257, 1);
    EXPECT_NEAR(level(128), 128 * 257, 1);
    // 2-bit grey: POV-Ray's middle levels 1 and 2 stand at 84 and 169 8-bit steps, not 85 and 170 (trace()).
    Bytes low = {0, 0x1B};  // 00 01 10 11
    const auto grid2 = read_height_grid(write("levels2.png", make_png(4, 1, 2, 0, low)), error, unsupported);
    ASSERT_TRUE(grid2) << error;
    EXPECT_NEAR(grid2->at(1, 0), 84 * 257, 1);
    EXPECT_NEAR(grid2->at(2, 0), 169 * 257, 1);
    EXPECT_GE(grid2->at(3, 0), 65534);
}

// The encoding a PNG declares, which POV-Ray 3.7 honours for image maps: an sRGB chunk first, else gAMA.
TEST(PngReader, DeclaredEncodingIsReadFromTheChunksBeforeTheImage) {
    const Bytes rows = rows_of(2, 2, 2);
    const auto plain = png_colour_info(write("plain.png", make_png(2, 2, 8, 0, rows)));
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->colour_type, 0);
    EXPECT_EQ(plain->bit_depth, 8);
    EXPECT_FALSE(plain->srgb);
    EXPECT_EQ(plain->file_gamma, 0.0);
    // make_png writes IHDR, then PLTE and tRNS; a gAMA chunk is put where a palette would go.
    Bytes gama = make_png(2, 2, 8, 0, rows);
    Bytes chunk_bytes;
    chunk(chunk_bytes, "gAMA", {0x00, 0x00, 0xB1, 0x8F});  // 45455
    gama.insert(gama.begin() + 33, chunk_bytes.begin(), chunk_bytes.end());
    const auto tagged = png_colour_info(write("gama.png", gama));
    ASSERT_TRUE(tagged);
    EXPECT_NEAR(tagged->file_gamma, 0.45455, 1e-12);
    EXPECT_FALSE(tagged->srgb);
    Bytes srgb = make_png(2, 2, 8, 2, rows_of(2, 2, 6));
    Bytes srgb_chunk;
    chunk(srgb_chunk, "sRGB", {0x00});
    srgb.insert(srgb.begin() + 33, srgb_chunk.begin(), srgb_chunk.end());
    const auto declared = png_colour_info(write("srgb.png", srgb));
    ASSERT_TRUE(declared);
    EXPECT_TRUE(declared->srgb);
    EXPECT_EQ(declared->colour_type, 2);
    EXPECT_FALSE(png_colour_info(write("not.png", Bytes{'G', 'I', 'F', '8', '9', 'a'})));
}

// A few bytes can claim billions of pixels: each header's claim is read before any pixel, and past the limit the
// file is refused with its size, before anything is allocated (through libpng, libjpeg and OpenImageIO alike).
TEST(ImageHeader, ClaimedSizesAreReadAndOversizedFilesRefused) {
    const Bytes png = make_png(3, 2, 8, 2, rows_of(3, 2, 9));
    ASSERT_TRUE(claimed_image_size(write("small.png", png)));
    EXPECT_EQ(claimed_image_size(write("small.png", png))->width, 3u);
    EXPECT_EQ(claimed_image_size(write("small.png", png))->height, 2u);
    Bytes huge = png;
    huge[16] = huge[17] = 0, huge[18] = 0xEA, huge[19] = 0x60;  // width 60000 (the CRC is not checked here)
    huge[20] = huge[21] = 0, huge[22] = 0xEA, huge[23] = 0x60;
    const fs::path huge_png = write("huge.png", huge);
    std::string error;
    EXPECT_FALSE(read_image(huge_png, error, nullptr, nullptr, nullptr, nullptr, nullptr, 1u << 20));
    EXPECT_EQ(error, "it claims 60000 x 60000 pixels, more than the 1048576 the memory limit allows (16 bytes each); "
                     "raise it with --max-memory MB");
    EXPECT_TRUE(read_image(write("small.png", png), error, nullptr, nullptr, nullptr, nullptr, nullptr, 6));
    EXPECT_FALSE(read_image(write("small.png", png), error, nullptr, nullptr, nullptr, nullptr, nullptr, 5));
    // GIF: the largest of the screen and the image descriptors.
    Bytes gif = {'G', 'I', 'F', '8', '9', 'a', 4, 0, 4, 0, 0, 0, 0};
    gif.insert(gif.end(), {',', 0, 0, 0, 0, 0x30, 0x75, 0x10, 0x27, 0, 2, 1, 0x44, 0, ';'});
    const auto g = claimed_image_size(write("big.gif", gif));
    ASSERT_TRUE(g);
    EXPECT_EQ(g->width, 30000u);
    EXPECT_EQ(g->height, 10000u);
    // JPEG: the frame header after an application segment.
    const Bytes jpeg = {0xFF, 0xD8, 0xFF, 0xE0, 0, 4, 0, 0, 0xFF, 0xC0, 0, 11, 8, 0x01, 0x02, 0x03, 0x04, 1, 1, 0x11, 0};
    const auto j = claimed_image_size(write("big.jpg", jpeg));
    ASSERT_TRUE(j);
    EXPECT_EQ(j->width, 0x0304u);
    EXPECT_EQ(j->height, 0x0102u);
    // PNM with a comment, and Targa by its extension.
    const std::string ppm = "P6\n# made by hand\n70000 5\n255\n";
    const auto p = claimed_image_size(write("big.ppm", Bytes(ppm.begin(), ppm.end())));
    ASSERT_TRUE(p);
    EXPECT_EQ(p->width, 70000u);
    EXPECT_EQ(p->height, 5u);
    Bytes tga(18, 0);
    tga[2] = 2, tga[12] = 0xFF, tga[13] = 0xFF, tga[14] = 0x10, tga[15] = 0x00;
    const auto t = claimed_image_size(write("big.tga", tga));
    ASSERT_TRUE(t);
    EXPECT_EQ(t->width, 65535u);
    EXPECT_EQ(t->height, 16u);
    EXPECT_FALSE(claimed_image_size(write("unknown.bin", Bytes{1, 2, 3})));
}

}  // namespace
}  // namespace wardray::render
