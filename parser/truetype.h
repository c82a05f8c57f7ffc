// TrueType fonts for `text`: the tables POV-Ray 3.7 reads (cmap, loca, glyf, hmtx, kern) and its glyph layout.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "parser/namespaces.h"

namespace wardray::parser {

/// A TrueType (or TrueType collection) font read the way POV-Ray 3.7 reads it, with its glyph cache: POV-Ray keeps
/// one cache per font for the whole scene, and which character first asked for a glyph can change its outline.
class TrueTypeFont {
public:
    /// Reads the font's tables; nothing, with a message in `error`, when the file is not a usable TrueType font.
    static std::optional<TrueTypeFont> load(const std::filesystem::path& path, std::string& error);

    /// The glyphs of `chars` (character codes) placed as POV-Ray 3.7 places them: the first glyph's left edge at
    /// x = 0, then advance widths and horizontal kerning, plus `offset` after every character. `utf8` selects
    /// POV-Ray's cmap preference for `charset utf8` (Unicode first) rather than ASCII (Macintosh Roman first).
    /// Nothing, with a message in `error`, when the glyph data is damaged.
    std::optional<std::vector<TextGlyph>> layout(const std::vector<std::uint32_t>& chars, const Vec3& offset,
                                                 bool utf8, std::string& error);

private:
    struct Glyph {
        std::int16_t x_min = 0;  ///< POV-Ray's glyph header bounds, in font units
        std::vector<std::vector<TextGlyph::Point>> contours;
        std::uint32_t c = 0;            ///< the character it was first read for
        std::uint32_t glyph_index = 0;  ///< from the cmap
        std::uint32_t metrics = 0;      ///< the glyph whose hmtx entry spaces it
    };
    struct KernPair {
        std::uint16_t left = 0;
        std::uint16_t right = 0;
        std::int16_t value = 0;
    };
    struct KernTable {
        std::uint16_t coverage = 0;
        std::vector<KernPair> pairs;
    };

    TrueTypeFont() = default;
    std::uint32_t glyph_index(std::uint32_t c, bool utf8);
    /// The cached glyph for a character (read on first use): its position in m_glyphs; `index` gets the glyph index.
    std::size_t glyph(std::uint32_t c, bool utf8, std::uint32_t& index);
    Glyph read_glyph(std::uint32_t index, std::uint32_t c) const;

    std::vector<std::uint8_t> m_data;
    std::uint32_t m_cmap = 0;
    std::uint32_t m_glyf = 0;
    int m_units_per_em = 2048;
    std::vector<std::uint32_t> m_loca;
    std::vector<std::uint16_t> m_advance;
    std::vector<std::int16_t> m_lsb;
    std::vector<KernTable> m_kern;
    std::vector<Glyph> m_glyphs;  ///< the cache, oldest first (POV-Ray searches newest first)
};

}  // namespace wardray::parser
