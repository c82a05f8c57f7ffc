// The atmosphere's statements: sky_sphere, fog and rainbow, read as POV-Ray 3.7's Parse_Skysphere, Parse_Fog and
// Parse_Rainbow read them (declared ones too).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "core/constants.h"
#include "parser/appearance_reader.h"
#include "parser/keywords.h"

namespace wardray::parser {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

}  // namespace

template <typename T>
bool AppearanceReader::read_declared(T& item, const char* kind) {
    expand_macros();
    const Token& first = peek();
    if (first.kind != TokenKind::Identifier || is_keyword(first.text)) return false;
    const Value* v = lookup(first.text);
    if (v == nullptr) fail_undeclared(first);
    // A number or colour is an item of the block (a fog's colour or distance), not a declared block.
    if (std::holds_alternative<Numeric>(*v)) return false;
    if (const auto* declared = std::get_if<Boxed<T>>(v)) {
        item = **declared;
    } else if (!std::holds_alternative<Unsupported>(*v)) {
        // An identifier of something not rendered yet was warned about where it was declared.
        fail(first, "'" + first.text + "' is " + value_kind_name(*v) + ", not " + kind);
    }
    next();
    return true;
}

SkySphere AppearanceReader::parse_sky_sphere(const Token& kw) {
    expect("{");
    SkySphere sky;
    const bool declared = read_declared(sky, "a sky_sphere");
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (parse_transform_item(t, tr)) {
            sky.transform = sky.transform.then(tr);
            continue;
        }
        next();
        if (is_punct(t, "}")) break;
        if (is_word(t, "pigment")) {
            // POV-Ray compat: a sky pigment starts from a fresh (black) pigment, not from the #default one.
            Pigment saved = std::exchange(m_default_pigment, Pigment{});
            try {
                sky.pigments.push_back(parse_pigment_body(t));
            } catch (...) {
                m_default_pigment = std::move(saved);
                throw;
            }
            m_default_pigment = std::move(saved);
        } else if (is_word(t, "emission")) {
            sky.emission = parse_color();
        } else {
            fail(t, "expected pigment, emission or a transform in sky_sphere but found " + describe_token(t));
        }
    }
    // A declared sky_sphere that is not rendered yet was warned about where it was declared.
    if (sky.pigments.empty() && !declared) fail(kw, "Empty sky_sphere statement.");
    return sky;
}

Fog AppearanceReader::parse_fog(const Token& kw) {
    expect("{");
    Fog fog;
    read_declared(fog, "a fog");
    fog.loc = make_diagnostic(Severity::Note, kw, "").loc;
    auto turbulence = [&fog]() -> Turbulence& {
        if (!fog.turbulence) fog.turbulence.emplace();
        return *fog.turbulence;
    };
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (is_word(t, "translate")) warn(t, "A fog's up vector can't be translated.");
        if (parse_transform_item(t, tr)) {
            // POV-Ray compat: rotate, scale, matrix and transform turn the up vector; translate is ignored.
            if (!is_word(t, "translate")) fog.up = tr.vector(fog.up);
            continue;
        }
        const Value* id = t.kind == TokenKind::Identifier ? lookup(t.text) : nullptr;
        const auto* numeric = id ? std::get_if<Numeric>(id) : nullptr;
        const bool bare_float = t.kind == TokenKind::Number || is_punct(t, "(") || is_punct(t, "-") ||
                                is_punct(t, "+") || (numeric != nullptr && numeric->n == 1);
        if (bare_float) {
            warn(t, "Should use distance keyword.");
            fog.distance = parse_float();
            continue;
        }
        if (starts_value(t)) {
            fog.color = parse_color();
            continue;
        }
        next();
        if (is_punct(t, "}")) break;
        if (is_word(t, "distance")) {
            fog.distance = parse_float();
        } else if (is_word(t, "fog_type")) {
            fog.type = static_cast<int>(parse_float());
            if (fog.type < 1 || fog.type > 2) warn(t, "Unknown fog type.");
        } else if (is_word(t, "fog_alt")) {
            fog.alt = parse_float();
        } else if (is_word(t, "fog_offset")) {
            fog.offset = parse_float();
        } else if (is_word(t, "turb_depth")) {
            fog.turb_depth = parse_float();
        } else if (is_word(t, "up")) {
            fog.up = parse_vector();
        } else if (is_word(t, "turbulence")) {
            turbulence().amount = parse_vector();
        } else if (is_word(t, "octaves")) {
            // POV-Ray compat: octaves are clamped to 1..10.
            turbulence().octaves = std::clamp(static_cast<int>(parse_float()), 1, 10);
        } else if (is_word(t, "omega")) {
            turbulence().omega = parse_float();
        } else if (is_word(t, "lambda")) {
            turbulence().lambda = parse_float();
        } else {
            fail(t, "expected distance, a colour, fog_type, fog_offset, fog_alt, up or turbulence in fog but found " +
                        describe_token(t));
        }
    }
    // POV-Ray compat: any other fog type is constant fog.
    if (fog.type != 2) fog.type = 1;
    if (fog.type == 2 && fog.alt == 0.0) warn_unsupported(kw, "ground fog with fog_alt 0");
    const double len = length(fog.up);
    if (len > 0.0) fog.up = fog.up / len;
    return fog;
}

Rainbow AppearanceReader::parse_rainbow(const Token& kw) {
    expect("{");
    Rainbow bow;
    // POV-Ray compat: the arc and fall-off angles default to 180 taken as radians (no bound at all), and the
    // direction to zero (an error unless given); the angles given are halved and turned into radians.
    bow.arc_angle = 180.0;
    bow.falloff_angle = 180.0;
    bow.antisolar = {};
    bow.angle = 0.0;
    bow.width = 0.0;
    // POV-Ray compat: a declared rainbow is copied as set up, and its angle and width (in radians by then) are
    // set up again as if given in degrees.
    read_declared(bow, "a rainbow");
    double angle = bow.angle;
    double width = bow.width;
    bool falloff_given = false;
    bool arc_given = false;
    bow.loc = make_diagnostic(Severity::Note, kw, "").loc;
    while (true) {
        expand_macros();
        const Token t = next();
        if (is_punct(t, "}")) break;
        if (is_word(t, "angle")) {
            angle = parse_float();
        } else if (is_word(t, "width")) {
            width = parse_float();
        } else if (is_word(t, "direction")) {
            bow.antisolar = parse_vector();
        } else if (is_word(t, "up")) {
            bow.up = parse_vector();
        } else if (is_word(t, "distance")) {
            bow.distance = parse_float();
        } else if (is_word(t, "jitter")) {
            bow.jitter = parse_float();
        } else if (is_word(t, "color_map") || is_word(t, "colour_map")) {
            Pigment p;
            p.pattern.type = Pattern::Type::Gradient;
            p.pattern.params->gradient = {1.0, 0.0, 0.0};
            p.color_map = parse_color_map(t);
            bow.pigment = std::move(p);
        } else if (is_word(t, "falloff_angle") || is_word(t, "arc_angle")) {
            const double a = parse_float();
            if (a < 0.0 || a > 360.0)
                fail(t, "Illegal " + std::string(is_word(t, "arc_angle") ? "arc" : "falloff") +
                            " angle in rainbow (Use value from 0 to 360 degrees).");
            (is_word(t, "arc_angle") ? bow.arc_angle : bow.falloff_angle) = a * kDegToRad / 2.0;
            (is_word(t, "arc_angle") ? arc_given : falloff_given) = true;
        } else {
            fail(t, "expected angle, width, direction, up, distance, jitter, color_map, arc_angle or falloff_angle "
                    "in rainbow but found " + describe_token(t));
        }
    }
    if (arc_given && !falloff_given) bow.falloff_angle = bow.arc_angle;
    if (bow.arc_angle < bow.falloff_angle) fail(kw, "Arc angle is smaller than falloff angle in rainbow.");
    bow.falloff_width = bow.arc_angle - bow.falloff_angle;
    if (std::fabs(dot(bow.antisolar, bow.antisolar)) < kPovEpsilon) fail(kw, "Rainbow's direction vector is zero.");
    if (std::fabs(dot(bow.up, bow.up)) < kPovEpsilon) fail(kw, "Rainbow's up vector is zero.");
    bow.antisolar = normalize(bow.antisolar);
    bow.up = normalize(bow.up);
    if (std::fabs(1.0 - std::fabs(dot(bow.up, bow.antisolar))) < kPovEpsilon)
        fail(kw, "Rainbow's up and direction vector are co-linear.");
    // Up made perpendicular to the antisolar direction, right completing the frame.
    bow.right = normalize(cross(bow.up, bow.antisolar));
    bow.up = normalize(cross(bow.antisolar, bow.right));
    // The bow's colour map spans [angle − width/2, angle + width/2].
    bow.angle = (angle - 0.5 * width) * kDegToRad;
    bow.width = width * kDegToRad;
    return bow;
}

}  // namespace wardray::parser
