// The pixel size image headers claim (PNG, GIF, JPEG, PNM, Targa), read from the file's first bytes only.
#include "render/image_header.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <vector>

namespace wardray::render {

namespace {

std::uint64_t be16(const unsigned char* p) { return (std::uint64_t{p[0]} << 8) | p[1]; }
std::uint64_t le16(const unsigned char* p) { return (std::uint64_t{p[1]} << 8) | p[0]; }
std::uint64_t be32(const unsigned char* p) { return (be16(p) << 16) | be16(p + 2); }

// PNG: the IHDR chunk comes first, width and height big-endian at bytes 16 and 20.
std::optional<ClaimedSize> png_size(const std::vector<unsigned char>& d) {
    if (d.size() < 24 || std::string(d.begin() + 12, d.begin() + 16) != "IHDR") return std::nullopt;
    return ClaimedSize{be32(&d[16]), be32(&d[20])};
}

// GIF: the logical screen, then every image descriptor (extensions and image data are runs of sub-blocks); the
// largest width and height of any of them.
std::optional<ClaimedSize> gif_size(std::ifstream& in) {
    auto byte = [&in]() { return in.get(); };
    auto skip = [&in](std::streamoff n) { in.seekg(n, std::ios::cur); };
    auto skip_sub_blocks = [&]() {
        for (int n = byte(); n > 0; n = byte()) skip(n);
    };
    unsigned char screen[7];
    in.seekg(6);
    if (!in.read(reinterpret_cast<char*>(screen), 7)) return std::nullopt;
    ClaimedSize size{le16(screen), le16(screen + 2)};
    if ((screen[4] & 0x80) != 0) skip(3 << ((screen[4] & 0x07) + 1));
    for (int c = byte(); in && c != ';' && c >= 0; c = byte()) {
        if (c == '!') {
            byte();
            skip_sub_blocks();
        } else if (c == ',') {
            unsigned char desc[9];
            if (!in.read(reinterpret_cast<char*>(desc), 9)) break;
            size.width = std::max(size.width, le16(desc + 4));
            size.height = std::max(size.height, le16(desc + 6));
            if ((desc[8] & 0x80) != 0) skip(3 << ((desc[8] & 0x07) + 1));
            byte();  // the LZW minimum code size
            skip_sub_blocks();
        } else {
            break;
        }
    }
    return size;
}

// JPEG: the segments up to the first frame header (SOF0-SOF15 but DHT, JPG and DAC), height then width.
std::optional<ClaimedSize> jpeg_size(std::ifstream& in) {
    in.seekg(2);
    while (in) {
        int m = in.get();
        if (m != 0xFF) return std::nullopt;
        while (m == 0xFF) m = in.get();
        if (m < 0 || m == 0xD9 || m == 0xDA) return std::nullopt;
        if (m == 0x01 || (m >= 0xD0 && m <= 0xD7)) continue;  // markers without a length
        unsigned char len[2];
        if (!in.read(reinterpret_cast<char*>(len), 2) || be16(len) < 2) return std::nullopt;
        if (m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC) {
            unsigned char sof[5];
            if (!in.read(reinterpret_cast<char*>(sof), 5)) return std::nullopt;
            return ClaimedSize{be16(sof + 3), be16(sof + 1)};
        }
        in.seekg(static_cast<std::streamoff>(be16(len)) - 2, std::ios::cur);
    }
    return std::nullopt;
}

// PNM (P1-P6): the magic, then width and height as decimal numbers between white space and # comments.
std::optional<ClaimedSize> pnm_size(const std::vector<unsigned char>& d) {
    std::size_t i = 2;
    std::uint64_t v[2] = {0, 0};
    for (std::uint64_t& value : v) {
        while (i < d.size() && (std::isspace(d[i]) || d[i] == '#')) {
            if (d[i] == '#')
                while (i < d.size() && d[i] != '\n') ++i;
            else
                ++i;
        }
        if (i >= d.size() || !std::isdigit(d[i])) return std::nullopt;
        for (; i < d.size() && std::isdigit(d[i]); ++i) value = std::min<std::uint64_t>(value * 10 + (d[i] - '0'), 1ull << 31);
    }
    return ClaimedSize{v[0], v[1]};
}

}  // namespace

std::optional<ClaimedSize> claimed_image_size(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::vector<unsigned char> head(256);
    in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    in.clear();
    const auto starts = [&head](const char* magic, std::size_t n) {
        return head.size() >= n && std::equal(magic, magic + n, head.begin(),
                                              [](char a, unsigned char b) { return static_cast<unsigned char>(a) == b; });
    };
    if (starts("\x89PNG\r\n\x1a\n", 8)) return png_size(head);
    if (starts("GIF8", 4)) return gif_size(in);
    if (starts("\xFF\xD8\xFF", 3)) return jpeg_size(in);
    if (head.size() >= 3 && head[0] == 'P' && head[1] >= '1' && head[1] <= '6') return pnm_size(head);
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".tga" && head.size() >= 18) return ClaimedSize{le16(&head[12]), le16(&head[14])};
    return std::nullopt;
}

std::optional<PngColourInfo> png_colour_info(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char head[33];
    if (!in.read(reinterpret_cast<char*>(head), sizeof(head))) return std::nullopt;
    const unsigned char magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (!std::equal(magic, magic + 8, head) || std::string(head + 12, head + 16) != "IHDR") return std::nullopt;
    PngColourInfo info;
    info.bit_depth = head[24];
    info.colour_type = head[25];
    // The chunks after IHDR up to the first IDAT (where the PNG specification puts sRGB and gAMA); each is length,
    // type, data and CRC. A few hundred at most: a hostile file cannot make this walk long.
    for (int chunks = 0; chunks < 512; ++chunks) {
        unsigned char header[8];
        if (!in.read(reinterpret_cast<char*>(header), sizeof(header))) break;
        const std::uint64_t length = be32(header);
        const std::string type(header + 4, header + 8);
        if (type == "IDAT" || type == "IEND" || length > (1u << 30)) break;
        if (type == "sRGB") info.srgb = true;
        if (type == "gAMA" && length == 4) {
            unsigned char value[4];
            if (!in.read(reinterpret_cast<char*>(value), sizeof(value))) break;
            info.file_gamma = static_cast<double>(be32(value)) / 100000.0;
            in.seekg(4, std::ios::cur);
            continue;
        }
        in.seekg(static_cast<std::streamoff>(length + 4), std::ios::cur);
    }
    return info;
}

std::string oversized_message(std::uint64_t width, std::uint64_t height, std::uint64_t max_pixels) {
    return "it claims " + std::to_string(width) + " x " + std::to_string(height) + " pixels, more than the " +
           std::to_string(max_pixels) + " the memory limit allows (16 bytes each); raise it with --max-memory MB";
}

std::optional<std::string> oversized_image(const std::filesystem::path& path, std::uint64_t max_pixels) {
    if (max_pixels == kAnyPixelCount) return std::nullopt;
    const std::optional<ClaimedSize> size = claimed_image_size(path);
    if (!size) return std::nullopt;
    // Both are below 2^32, so the product does not overflow.
    if (size->width * size->height <= max_pixels) return std::nullopt;
    return oversized_message(size->width, size->height, max_pixels);
}

}  // namespace wardray::render
