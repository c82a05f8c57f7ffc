// GIF decoding to palette indices: the file's blocks (GIF89a spec, sections 17-24) and its variable-width LZW
// codes (section 22 and appendix F), written from the specification.
#include "render/gif_reader.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>

namespace wardray::render {

namespace {

// The bytes of the file with a read position; reads past the end give -1.
struct Bytes {
    std::vector<std::uint8_t> data;
    std::size_t at = 0;
    int next() { return at < data.size() ? data[at++] : -1; }
    bool skip(std::size_t n) {
        if (data.size() - at < n) return false;
        at += n;
        return true;
    }
};

// The image data's sub-blocks joined into one code stream.
std::vector<std::uint8_t> read_sub_blocks(Bytes& in, bool& ok) {
    std::vector<std::uint8_t> out;
    ok = true;
    for (int n = in.next(); n != 0; n = in.next()) {
        if (n < 0 || in.data.size() - in.at < static_cast<std::size_t>(n)) {
            ok = false;
            return out;
        }
        out.insert(out.end(), in.data.begin() + static_cast<std::ptrdiff_t>(in.at),
                   in.data.begin() + static_cast<std::ptrdiff_t>(in.at) + n);
        in.at += static_cast<std::size_t>(n);
    }
    return out;
}

// LZW codes of min_size + 1 to 12 bits, least significant bit first; `count` indices are wanted.
bool lzw_decode(const std::vector<std::uint8_t>& codes, int min_size, std::size_t count, std::vector<std::uint8_t>& out) {
    if (min_size < 2 || min_size > 8) return false;
    const int clear = 1 << min_size, end = clear + 1;
    std::array<std::uint16_t, 4096> prefix{};
    std::array<std::uint8_t, 4096> suffix{};
    std::array<std::uint8_t, 4097> stack{};
    for (int i = 0; i < clear; ++i) suffix[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
    int size = min_size + 1, next_code = clear + 2, prev = -1;
    std::uint8_t first = 0;
    std::size_t bit = 0;
    const std::size_t bits = codes.size() * 8;
    out.clear();
    out.reserve(count);
    while (out.size() < count && bit + static_cast<std::size_t>(size) <= bits) {
        int code = 0;
        for (int i = 0; i < size; ++i, ++bit) code |= ((codes[bit >> 3] >> (bit & 7)) & 1) << i;
        if (code == clear) {
            size = min_size + 1;
            next_code = clear + 2;
            prev = -1;
            continue;
        }
        if (code == end) break;
        if (prev < 0) {
            // The first code after a clear is a single index.
            if (code >= clear) return false;
            first = static_cast<std::uint8_t>(code);
            out.push_back(first);
            prev = code;
            continue;
        }
        const int in_code = code;
        std::size_t sp = 0;
        if (code >= next_code) {
            // A code not yet in the table: the previous string and its own first index.
            if (code > next_code) return false;
            stack[sp++] = first;
            code = prev;
        }
        while (code >= clear) {
            stack[sp++] = suffix[static_cast<std::size_t>(code)];
            code = prefix[static_cast<std::size_t>(code)];
        }
        first = static_cast<std::uint8_t>(code);
        stack[sp++] = first;
        while (sp > 0 && out.size() < count) out.push_back(stack[--sp]);
        if (next_code < 4096) {
            prefix[static_cast<std::size_t>(next_code)] = static_cast<std::uint16_t>(prev);
            suffix[static_cast<std::size_t>(next_code)] = first;
            ++next_code;
            if (next_code == (1 << size) && size < 12) ++size;
        }
        prev = in_code;
    }
    return true;
}

}  // namespace

std::optional<GifIndices> read_gif_indices(const std::filesystem::path& path, std::string& error) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        error = "cannot open the file";
        return std::nullopt;
    }
    Bytes in{std::vector<std::uint8_t>(std::istreambuf_iterator<char>(file), {})};
    const auto& d = in.data;
    if (d.size() < 13 || d[0] != 'G' || d[1] != 'I' || d[2] != 'F') {
        error = "not a GIF file";
        return std::nullopt;
    }
    in.at = 13;
    // The global colour table: 3 bytes for each of 2^(n+1) entries.
    std::vector<std::uint8_t> global_table;
    if ((d[10] & 0x80) != 0) {
        const std::size_t size = 3u << ((d[10] & 0x07) + 1);
        if (!in.skip(size)) {
            error = "truncated colour table";
            return std::nullopt;
        }
        global_table.assign(d.begin() + 13, d.begin() + 13 + static_cast<std::ptrdiff_t>(size));
    }
    int transparent = -1;
    for (int c = in.next(); c >= 0; c = in.next()) {
        if (c == ';') break;
        if (c == '!') {
            // An extension: its label, then sub-blocks; a graphic control extension (0xF9) may name a
            // transparent index.
            bool ok = true;
            const int label = in.next();
            if (label < 0) break;
            const std::vector<std::uint8_t> body = read_sub_blocks(in, ok);
            if (!ok) break;
            if (label == 0xF9 && body.size() >= 4) transparent = (body[0] & 1) != 0 ? body[3] : -1;
            continue;
        }
        if (c != ',') break;
        // The image descriptor: position, size, flags; then a local colour table, then the LZW data.
        if (d.size() - in.at < 9) break;
        const std::uint8_t* desc = d.data() + in.at;
        in.at += 9;
        GifIndices image;
        image.screen_width = d[6] | (d[7] << 8);
        image.screen_height = d[8] | (d[9] << 8);
        image.left = desc[0] | (desc[1] << 8);
        image.top = desc[2] | (desc[3] << 8);
        image.width = desc[4] | (desc[5] << 8);
        image.height = desc[6] | (desc[7] << 8);
        image.transparent = transparent;
        const bool interlaced = (desc[8] & 0x40) != 0;
        if ((desc[8] & 0x80) != 0) {
            const std::size_t size = 3u << ((desc[8] & 0x07) + 1);
            if (!in.skip(size)) break;
            image.palette.assign(d.begin() + static_cast<std::ptrdiff_t>(in.at - size),
                                 d.begin() + static_cast<std::ptrdiff_t>(in.at));
        } else {
            image.palette = global_table;
        }
        const int min_size = in.next();
        bool ok = true;
        const std::vector<std::uint8_t> codes = read_sub_blocks(in, ok);
        const std::size_t count = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
        std::vector<std::uint8_t> decoded;
        if (!ok || !lzw_decode(codes, min_size, count, decoded)) break;
        decoded.resize(count, 0);
        if (!interlaced) {
            image.index = std::move(decoded);
        } else {
            // Interlaced rows come in four passes: every 8th from 0 and from 4, every 4th from 2, every 2nd from 1.
            image.index.resize(count);
            std::size_t row = 0;
            const int starts[4] = {0, 4, 2, 1}, steps[4] = {8, 8, 4, 2};
            for (int pass = 0; pass < 4; ++pass)
                for (int y = starts[pass]; y < image.height; y += steps[pass], ++row)
                    std::copy_n(decoded.begin() + static_cast<std::ptrdiff_t>(row * image.width), image.width,
                                image.index.begin() + static_cast<std::ptrdiff_t>(y) * image.width);
        }
        return image;
    }
    error = "no readable image in the GIF file";
    return std::nullopt;
}

bool read_gif_rgb(const std::filesystem::path& path, int& width, int& height, std::vector<float>& rgb) {
    std::string error;
    const std::optional<GifIndices> gif = read_gif_indices(path, error);
    if (!gif || gif->screen_width <= 0 || gif->screen_height <= 0 || gif->palette.empty()) return false;
    const std::size_t entries = gif->palette.size() / 3;
    for (const std::uint8_t i : gif->index)
        if (i >= entries && i != gif->transparent) return false;
    width = gif->screen_width;
    height = gif->screen_height;
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    rgb.assign(n * 3, 0.0f);
    // The image's window on the screen, clipped to it; each sample as OpenImageIO converts 8-bit ones to float.
    for (int wy = 0; wy < gif->height; ++wy) {
        const int y = gif->top + wy;
        if (y >= height) break;
        for (int wx = 0; wx < gif->width; ++wx) {
            const int x = gif->left + wx;
            if (x >= width) break;
            const std::uint8_t i = gif->index[static_cast<std::size_t>(wy) * gif->width + wx];
            if (i == gif->transparent) continue;
            const std::size_t at = static_cast<std::size_t>(y) * width + x;
            for (int c = 0; c < 3; ++c)
                rgb[at * 3 + c] = static_cast<float>(gif->palette[i * 3u + c]) * (1.0f / 255.0f);
        }
    }
    return true;
}

}  // namespace wardray::render
