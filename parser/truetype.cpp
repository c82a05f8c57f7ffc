// TrueType reading as POV-Ray 3.7 does it (truetype.cpp of 3.7.0): the same table choices, the same glyph header
// bookkeeping and the same spacing rules, so that text lands where POV-Ray puts it.
#include "parser/truetype.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "core/large_stack.h"

namespace wardray::parser {

namespace {

// TrueType glyph flags and composite-glyph flags (Apple TrueType Reference Manual, 'glyf').
constexpr std::uint8_t kOnCurve = 0x01;
constexpr std::uint8_t kXShort = 0x02;
constexpr std::uint8_t kYShort = 0x04;
constexpr std::uint8_t kRepeat = 0x08;
constexpr std::uint8_t kXSame = 0x10;  // with kXShort: the short x is positive
constexpr std::uint8_t kYSame = 0x20;
constexpr std::uint16_t kArgsAreWords = 0x0001;
constexpr std::uint16_t kArgsAreXY = 0x0002;
constexpr std::uint16_t kHaveScale = 0x0008;
constexpr std::uint16_t kMoreComponents = 0x0020;
constexpr std::uint16_t kHaveXYScale = 0x0040;
constexpr std::uint16_t kHaveTwoByTwo = 0x0080;
constexpr std::uint16_t kUseMyMetrics = 0x0200;
// 'kern' coverage bits.
constexpr std::uint16_t kKernHorizontal = 0x01;
constexpr std::uint16_t kKernMinimum = 0x02;
constexpr std::uint16_t kKernCrossStream = 0x04;
constexpr std::uint16_t kKernOverride = 0x08;

// Thrown on the parser's large stack, so it clears AddressSanitizer's stale poison as StatementError does.
struct FontError : std::runtime_error {
    explicit FontError(const char* what) : std::runtime_error(what) { unpoison_stack_above_here(); }
};

// Big-endian reads with a cursor; reading past the end is an error, as in POV-Ray.
class Reader {
public:
    explicit Reader(const std::vector<std::uint8_t>& data) : m_data(data) {}
    void seek(std::size_t pos) { m_pos = pos; }
    void skip(std::size_t n) { m_pos += n; }
    std::size_t tell() const { return m_pos; }
    std::uint8_t u8() {
        if (m_pos >= m_data.size()) throw FontError("cannot read TrueType font file: unexpected end of data");
        return m_data[m_pos++];
    }
    std::uint16_t u16() {
        const std::uint16_t hi = u8();
        return static_cast<std::uint16_t>((hi << 8) | u8());
    }
    std::int16_t s16() { return static_cast<std::int16_t>(u16()); }
    std::uint32_t u32() {
        const std::uint32_t hi = u16();
        return (hi << 16) | u16();
    }

private:
    const std::vector<std::uint8_t>& m_data;
    std::size_t m_pos = 0;
};

// A glyph as read from 'glyf' before its contours are split (POV-Ray's GlyphOutline).
struct Outline {
    int num_contours = 0;
    std::int16_t x_min = 0, y_min = 0, x_max = 0, y_max = 0;
    std::vector<std::uint16_t> end_points;
    std::vector<std::uint8_t> flags;
    std::vector<double> x, y;
    std::uint32_t metrics = 0;
};

// POV-Ray compat: composite glyphs widen the FWord header with em-unit doubles, truncated on assignment.
void widen(std::int16_t& bound, double v, bool lower) {
    if (lower ? v < bound : v > bound) bound = static_cast<std::int16_t>(v);
}

Outline read_outline(Reader& in, const std::vector<std::uint32_t>& loca, std::uint32_t glyf, int units_per_em,
                     std::uint32_t index, std::uint32_t c, int depth) {
    Outline g;
    g.metrics = index;
    if (depth > 16) throw FontError("TrueType composite glyphs nest too deeply");
    // POV-Ray compat: a space is never read from the font, whatever its glyph holds.
    if (c == ' ') return g;
    // POV-Ray reads the header even for an empty glyph (the next glyph's data); an index past the table reads none.
    if (index >= loca.size()) return g;
    in.seek(std::size_t(glyf) + loca[index]);
    g.num_contours = in.s16();
    g.x_min = in.s16();
    g.y_min = in.s16();
    g.x_max = in.s16();
    g.y_max = in.s16();
    const int nc = g.num_contours;
    if (nc > 0) {
        g.end_points.resize(nc);
        for (int i = 0; i < nc; ++i) g.end_points[i] = in.u16();
        in.skip(in.u16());  // instructions
        const std::size_t n = std::size_t(g.end_points[nc - 1]) + 1;
        g.flags.assign(n, 0);
        for (std::size_t i = 0; i < n; ++i) {
            g.flags[i] = in.u8();
            if (g.flags[i] & kRepeat) {
                for (int repeat = in.u8(); repeat > 0; --repeat, ++i)
                    if (i + 1 < n) g.flags[i + 1] = g.flags[i];
            }
        }
        g.x.resize(n);
        g.y.resize(n);
        for (int axis = 0; axis < 2; ++axis) {
            const std::uint8_t short_bit = axis == 0 ? kXShort : kYShort;
            const std::uint8_t same_bit = axis == 0 ? kXSame : kYSame;
            std::int16_t coord = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const std::uint8_t flag = g.flags[i];
                if (flag & short_bit) {
                    const int d = in.u8();
                    coord = static_cast<std::int16_t>((flag & same_bit) ? coord + d : coord - d);
                } else if (!(flag & same_bit)) {
                    coord = static_cast<std::int16_t>(coord + in.s16());
                }
                // POV-Ray widens the header to the glyph's own extremes.
                if (axis == 0) {
                    g.x_max = std::max(g.x_max, coord);
                    g.x_min = std::min(g.x_min, coord);
                    g.x[i] = double(coord) / units_per_em;
                } else {
                    g.y_max = std::max(g.y_max, coord);
                    g.y_min = std::min(g.y_min, coord);
                    g.y[i] = double(coord) / units_per_em;
                }
            }
        }
    } else if (nc < 0) {
        g.num_contours = 0;
        std::uint16_t flags = 0;
        do {
            flags = in.u16();
            const std::uint16_t sub_index = in.u16();
            int arg1 = 0;
            int arg2 = 0;
            if (flags & kArgsAreWords) {
                arg1 = in.s16();
                arg2 = in.s16();
            } else {
                // POV-Ray compat: byte arguments are read unsigned.
                const std::uint16_t both = in.u16();
                arg1 = (both >> 8) & 0xFF;
                arg2 = both & 0xFF;
            }
            double xscale = 1, yscale = 1, scale01 = 0, scale10 = 0;
            if (flags & kHaveScale) {
                xscale = yscale = in.s16() / 16384.0;
            } else if (flags & kHaveXYScale) {
                xscale = in.s16() / 16384.0;
                yscale = in.s16() / 16384.0;
            } else if (flags & kHaveTwoByTwo) {
                xscale = in.s16() / 16384.0;
                scale01 = in.s16() / 16384.0;
                scale10 = in.s16() / 16384.0;
                yscale = in.s16() / 16384.0;
            }
            // POV-Ray compat: components placed by matching points are left out.
            if (!(flags & kArgsAreXY)) continue;
            const double xoff = double(arg1) / units_per_em;
            const double yoff = double(arg2) / units_per_em;
            if (flags & kUseMyMetrics) g.metrics = sub_index;
            const std::size_t resume = in.tell();
            const Outline sub = read_outline(in, loca, glyf, units_per_em, sub_index, c, depth + 1);
            in.seek(resume);
            if (sub.num_contours == 0) continue;
            const std::uint16_t n = static_cast<std::uint16_t>(g.x.size());
            for (int i = 0; i < sub.num_contours; ++i)
                g.end_points.push_back(static_cast<std::uint16_t>(sub.end_points[i] + n));
            g.num_contours += sub.num_contours;
            for (std::size_t i = 0; i < sub.x.size(); ++i) {
                g.flags.push_back(sub.flags[i]);
                // POV-Ray compat: its order of the 2x2 terms.
                const double x = xscale * sub.x[i] + scale01 * sub.y[i] + xoff;
                const double y = scale10 * sub.x[i] + yscale * sub.y[i] + yoff;
                g.x.push_back(x);
                g.y.push_back(y);
                widen(g.x_min, x, true);
                widen(g.x_max, x, false);
                widen(g.y_min, y, true);
                widen(g.y_max, y, false);
            }
        } while (flags & kMoreComponents);
    }
    return g;
}

}  // namespace

std::optional<TrueTypeFont> TrueTypeFont::load(const std::filesystem::path& path, std::string& error) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        error = "cannot open font file";
        return std::nullopt;
    }
    TrueTypeFont font;
    font.m_data.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    try {
        Reader in(font.m_data);
        // A collection: POV-Ray takes its first font.
        if (in.u32() == 0x74746366u) {  // 'ttcf'
            in.skip(8);
            in.seek(in.u32());
        } else {
            in.seek(0);
        }
        in.skip(4);
        const int num_tables = in.u16();
        in.skip(6);
        std::uint32_t head = 0, loca = 0, maxp = 0, kern = 0, hhea = 0, hmtx = 0;
        // POV-Ray compat: only the first 40 table records are looked at.
        for (int i = 0; i < num_tables && i < 40; ++i) {
            const std::uint32_t tag = in.u32();
            in.skip(4);
            const std::uint32_t offset = in.u32();
            in.skip(4);
            switch (tag) {
                case 0x636d6170u: font.m_cmap = offset; break;  // cmap
                case 0x676c7966u: font.m_glyf = offset; break;  // glyf
                case 0x68656164u: head = offset; break;         // head
                case 0x6c6f6361u: loca = offset; break;         // loca
                case 0x6d617870u: maxp = offset; break;         // maxp
                case 0x6b65726eu: kern = offset; break;         // kern
                case 0x68686561u: hhea = offset; break;         // hhea
                case 0x686d7478u: hmtx = offset; break;         // hmtx
                default: break;
            }
        }
        if (!font.m_cmap || !font.m_glyf || !head || !loca || !hhea || !hmtx || !maxp)
            throw FontError("invalid TrueType font headers");
        in.seek(head + 12);
        if (in.u32() != 0x5F0F3CF5u) throw FontError("cannot read TrueType font");
        in.seek(head + 18);
        font.m_units_per_em = in.u16();
        in.seek(head + 50);
        const int index_to_loc = in.s16();
        if (font.m_units_per_em == 0) throw FontError("invalid TrueType font data (unitsPerEm is 0)");
        in.seek(maxp + 4);
        const int num_glyphs = in.u16();
        in.seek(loca);
        font.m_loca.resize(num_glyphs);
        for (auto& l : font.m_loca) l = index_to_loc == 0 ? std::uint32_t(in.u16()) << 1 : in.u32();
        in.seek(hhea + 34);
        const int num_metrics = std::min<int>(in.u16(), num_glyphs);
        in.seek(hmtx);
        font.m_advance.resize(num_glyphs);
        font.m_lsb.resize(num_glyphs);
        std::uint16_t last_advance = 0;
        for (int i = 0; i < num_glyphs; ++i) {
            if (i < num_metrics) last_advance = in.u16();
            font.m_advance[i] = last_advance;
            font.m_lsb[i] = in.s16();
        }
        if (kern) {
            in.seek(kern + 2);
            const int n_tables = in.u16();
            for (int i = 0; i < n_tables; ++i) {
                KernTable table;
                in.skip(2);
                const std::uint16_t length = in.u16();
                table.coverage = in.u16();
                if ((table.coverage >> 8) == 0) {
                    const int n_pairs = in.u16();
                    in.skip(6);
                    table.pairs.resize(n_pairs);
                    for (KernPair& p : table.pairs) {
                        p.left = in.u16();
                        p.right = in.u16();
                        p.value = in.s16();
                    }
                } else {
                    in.skip(length - 6u);  // only format 0 is read
                }
                font.m_kern.push_back(std::move(table));
            }
        }
    } catch (const FontError& e) {
        error = e.what();
        return std::nullopt;
    }
    return font;
}

std::uint32_t TrueTypeFont::glyph_index(std::uint32_t c, bool utf8) {
    Reader in(m_data);
    in.seek(m_cmap + 2);
    const int n_tables = in.u16();
    const std::size_t records = in.tell();
    // POV-Ray compat: platforms in order of preference, the first subtable of a readable format wins.
    const int ascii_order[4] = {1, 3, 0, 3};
    const int utf8_order[4] = {0, 3, 1, 3};
    for (const int platform : utf8 ? utf8_order : ascii_order) {
        in.seek(records);
        for (int i = 0; i < n_tables; ++i) {
            const int platform_id = in.u16();
            in.skip(2);
            const std::uint32_t offset = in.u32();
            if (platform_id != platform) continue;
            const std::size_t next = in.tell();
            const std::size_t table = std::size_t(m_cmap) + offset;
            in.seek(table);
            const int format = in.u16();
            in.skip(4);
            if (format == 0) {
                in.skip(c);
                return in.u8();
            }
            if (format == 6) {
                const std::uint32_t first = in.u16();
                const std::uint32_t count = in.u16();
                if (c < first || c >= first + count) return 0;
                in.skip(2 * (c - first));
                return in.u16();
            }
            if (format == 4) {
                const int seg_count = in.u16() >> 1;
                in.skip(6);
                const std::size_t ends = in.tell();
                const std::size_t starts = ends + 2 * seg_count + 2;
                const std::size_t deltas = starts + 2 * seg_count;
                const std::size_t range_offsets = deltas + 2 * seg_count;
                auto at = [&](std::size_t base, int k) {
                    in.seek(base + 2 * std::size_t(k));
                    return in.u16();
                };
                std::uint32_t search = c;
                for (int pass = 0; pass < 2; ++pass) {
                    std::uint32_t index = 0;
                    for (int k = 0; k < seg_count; ++k) {
                        if (search > at(ends, k)) continue;
                        const std::uint32_t start = at(starts, k);
                        if (search >= start) {
                            const std::uint16_t delta = at(deltas, k);
                            const std::uint16_t range = at(range_offsets, k);
                            if (range == 0) {
                                index = search + delta;
                            } else {
                                in.seek(range_offsets + 2 * std::size_t(k) + range + 2 * (search - start));
                                index = in.u16();
                                if (index != 0) index += delta;
                            }
                        }
                        break;
                    }
                    // POV-Ray compat: the glyph index is a 16-bit value, tested for zero before it is cut.
                    if (index != 0 || search >= 0x100) return index & 0xFFFFu;
                    // Symbol fonts keep their characters in the private use area.
                    search += 0xF000;
                }
                return 0;
            }
            in.seek(next);
        }
    }
    return 0;
}

TrueTypeFont::Glyph TrueTypeFont::read_glyph(std::uint32_t index, std::uint32_t c) const {
    Reader in(m_data);
    const Outline o = read_outline(in, m_loca, m_glyf, m_units_per_em, index, c, 0);
    Glyph g;
    g.x_min = o.x_min;
    g.c = c;
    g.glyph_index = index;
    g.metrics = o.metrics;
    std::size_t first = 0;
    for (int i = 0; i < o.num_contours; ++i) {
        const std::size_t last = o.end_points[i];
        if (last < first || last >= o.x.size()) throw FontError("damaged TrueType glyph outline");
        std::vector<TextGlyph::Point> contour;
        for (std::size_t k = first; k <= last; ++k) contour.push_back({o.x[k], o.y[k], (o.flags[k] & kOnCurve) != 0});
        g.contours.push_back(std::move(contour));
        first = last + 1;
    }
    return g;
}

std::size_t TrueTypeFont::glyph(std::uint32_t c, bool utf8, std::uint32_t& index) {
    // POV-Ray compat: the cache is searched by character, then by glyph index, newest first.
    for (std::size_t k = m_glyphs.size(); k-- > 0;)
        if (m_glyphs[k].c == c) {
            index = m_glyphs[k].glyph_index;
            return k;
        }
    index = glyph_index(c, utf8);
    for (std::size_t k = m_glyphs.size(); k-- > 0;)
        if (m_glyphs[k].glyph_index == index) return k;
    m_glyphs.push_back(read_glyph(index, c));
    return m_glyphs.size() - 1;
}

std::optional<std::vector<TextGlyph>> TrueTypeFont::layout(const std::vector<std::uint32_t>& chars,
                                                           const Vec3& offset, bool utf8, std::string& error) {
    std::vector<TextGlyph> out;
    try {
        const double funit = 1.0 / m_units_per_em;
        auto advance = [&](std::uint32_t m) { return m < m_advance.size() ? int(m_advance[m]) : 0; };
        auto lsb = [&](std::uint32_t m) { return m < m_lsb.size() ? int(m_lsb[m]) : 0; };
        Vec3 total;
        std::uint32_t last_index = 0;
        for (std::size_t i = 0; i < chars.size(); ++i) {
            std::uint32_t index = 0;
            const Glyph& g = m_glyphs[glyph(chars[i], utf8, index)];
            TextGlyph placed;
            placed.contours = g.contours;
            if (i == 0) {
                // The first glyph's left edge at the origin; the next pen position excludes its left bearing.
                placed.offset = {-g.x_min * funit, 0.0, 0.0};
                total.x = (advance(g.metrics) - lsb(g.metrics)) * funit;
            } else {
                std::int16_t kern_x = 0, kern_y = 0;
                std::int16_t min_x = static_cast<std::int16_t>(-m_units_per_em), min_y = min_x;
                for (const KernTable& table : m_kern) {
                    // POV-Ray compat: every subtable is read with the first subtable's coverage bits.
                    const std::uint16_t coverage = m_kern.front().coverage;
                    if (!(coverage & kKernHorizontal)) continue;
                    for (const KernPair& p : table.pairs) {
                        if (p.left == last_index && p.right == g.metrics) {
                            if (coverage & kKernMinimum) {
                                (coverage & kKernCrossStream ? min_y : min_x) = p.value;
                            } else if (coverage & kKernCrossStream) {
                                if (p.value == std::int16_t(0x8000)) kern_y = 0;
                                else kern_y = static_cast<std::int16_t>((coverage & kKernOverride) ? p.value : kern_y + p.value);
                            } else {
                                kern_x = static_cast<std::int16_t>((coverage & kKernOverride) ? p.value : kern_x + p.value);
                            }
                            break;
                        }
                        if (p.left > last_index) break;
                    }
                }
                kern_x = std::max(kern_x, min_x);
                kern_y = std::max(kern_y, min_y);
                // POV-Ray compat: glyphs move in x and y only; the z of `offset` is never applied.
                placed.offset = {total.x + (lsb(g.metrics) - g.x_min + kern_x) * funit, total.y + kern_y * funit, 0.0};
                total.x += (advance(g.metrics) + kern_x) * funit;
            }
            total += offset;
            out.push_back(std::move(placed));
            last_index = index;
        }
    } catch (const FontError& e) {
        error = e.what();
        return std::nullopt;
    }
    return out;
}

}  // namespace wardray::parser
