// Media: POV-Ray 3.7's `media { }` block (Parse_Media) and its `density { }` patterns.
#include <cmath>

#include "parser/keyword_table.h"
#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

Media AppearanceReader::parse_media_body(const Token& kw) {
    expect("{");
    Media m;
    m.loc = make_diagnostic(Severity::Note, kw, "").loc;
    // POV-Ray compat: before 3.5 the defaults were method 1, intervals 10, one sample.
    if (m_version < 3.5) {
        m.method = 1;
        m.intervals = 10;
        m.min_samples = 1;
        m.max_samples = 1;
    }
    expand_macros();
    if (const Token& first = peek(); first.kind == TokenKind::Identifier && !is_keyword(first.text) &&
                                     lookup(first.text) != nullptr) {
        // A declared media, which the items after it modify.
        const Value* v = lookup(first.text);
        if (const auto* declared = std::get_if<Boxed<Media>>(v)) m = **declared;
        else fail(first, "'" + first.text + "' is " + value_kind_name(*v) + ", not a media");
        next();
    }
    using Item = void (*)(AppearanceReader&, Media&, const Token&);
    static const KeywordTable<Item> items = {
        {"intervals",
         [](AppearanceReader& r, Media& m, const Token& kw) {
             m.intervals = static_cast<int>(r.parse_float());
             if (m.intervals < 1) r.fail(kw, "At least one interval is needed in media.");
         }},
        {"samples",
         [](AppearanceReader& r, Media& m, const Token& kw) {
             m.min_samples = static_cast<int>(r.parse_float());
             r.accept(",");
             m.max_samples = r.starts_value(r.peek()) ? static_cast<int>(r.parse_float()) : m.min_samples;
             if (m.min_samples < 1) r.fail(kw, "At least one sample per interval is needed in media.");
             if (m.max_samples < m.min_samples)
                 r.fail(kw, "Maximum number of samples per interval smaller than minimum number.");
         }},
        {"method",
         [](AppearanceReader& r, Media& m, const Token& kw) {
             m.method = static_cast<int>(r.parse_float());
             if (m.method < 1 || m.method > 3) r.fail(kw, "Sample method choices are 1, 2, or 3.");
         }},
        {"jitter", [](AppearanceReader& r, Media& m, const Token&) { m.jitter = r.parse_float(); }},
        {"aa_threshold",
         [](AppearanceReader& r, Media& m, const Token& kw) {
             m.aa_threshold = r.parse_float();
             if (m.aa_threshold <= 0.0) r.fail(kw, "aa_threshold in media must be greater than zero.");
         }},
        {"aa_level",
         [](AppearanceReader& r, Media& m, const Token& kw) {
             m.aa_level = static_cast<int>(r.parse_float());
             if (m.aa_level < 1) r.fail(kw, "aa_level in media must be at least one.");
         }},
        {"collect",
         [](AppearanceReader& r, Media&, const Token&) {
             // Only photons read it; wardray has no photons yet, so it changes nothing.
             if (r.starts_value(r.peek())) r.parse_float();
         }},
        {"absorption", [](AppearanceReader& r, Media& m, const Token&) { m.absorption = r.parse_color(); }},
        {"emission", [](AppearanceReader& r, Media& m, const Token&) { m.emission = r.parse_color(); }},
        {"scattering", [](AppearanceReader& r, Media& m, const Token& kw) { r.parse_media_scattering(m, kw); }},
        {"confidence",
         [](AppearanceReader& r, Media& m, const Token& kw) {
             m.confidence = r.parse_float();
             if (m.confidence < 0.0 || m.confidence >= 1.0) r.fail(kw, "Illegal confidence value in media.");
         }},
        {"variance", [](AppearanceReader& r, Media& m, const Token&) { m.variance = r.parse_float(); }},
        {"ratio", [](AppearanceReader& r, Media& m, const Token&) { m.ratio = r.parse_float(); }},
        {"density",
         [](AppearanceReader& r, Media& m, const Token& kw) {
             // POV-Ray compat: each density is put in front of the list (they multiply, so order only matters
             // for the transforms that follow).
             m.densities.insert(m.densities.begin(), r.parse_density_body(kw));
         }},
    };
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (parse_transform_item(t, tr)) {
            // POV-Ray compat: a transform in the media block moves the densities given before it.
            transform_media(m, tr);
            continue;
        }
        next();
        if (is_punct(t, "}")) break;
        const Item* item = t.kind == TokenKind::Identifier ? items.find(t.text) : nullptr;
        if (item == nullptr) fail(t, "expected a media item but found " + describe_token(t));
        (*item)(*this, m, t);
    }
    return m;
}

void AppearanceReader::parse_media_scattering(Media& m, const Token& kw) {
    AppearanceReader& r = *this;
    r.expect("{");
    const Token& at = r.peek();
    m.scattering_type = static_cast<int>(r.parse_float());
    if (m.scattering_type < 1 || m.scattering_type > 5) r.warn(at, "Unknown atmospheric scattering type.");
    r.accept(",");
    m.scattering = r.parse_color();
    while (true) {
        const Token t = r.next();
        if (r.is_punct(t, "}")) return;
        if (r.is_word(t, "eccentricity")) {
            if (m.scattering_type != 5) r.fail(t, "Eccentricity cannot be used with this scattering type.");
            m.eccentricity = r.parse_float();
        } else if (r.is_word(t, "extinction")) {
            m.extinction = r.parse_float();
        } else {
            r.fail(t, "expected eccentricity, extinction or '}' in " + kw.text + " but found " + describe_token(t));
        }
    }
}

Pigment Parser::parse_density_body(const Token& kw) {
    expect("{");
    // POV-Ray compat (Parse_Media_Density_Pattern): a density starts black with no pattern, not from #default.
    Pigment p;
    p.loc = make_diagnostic(Severity::Note, kw, "").loc;
    parse_pigment_start(p);
    parse_pigment_items(p, kw, "}");
    return p;
}

}  // namespace wardray::parser
