// Photon blocks: global_settings `photons { }`, an object's `photons { }` and a light's `photons { }`, read as
// POV-Ray 3.7 reads them (Parse_Global_Settings, Parse_Object_Mods, Parse_Light_Source), with its defaults, its
// warnings and its CheckPassThru fix-ups.
#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

void ObjectReader::read_object_photons(ObjectReader& r, ObjectValue& ov, const Token&, ModifierState&) {
    // POV-Ray's Allow_Float(1.0): the value when one follows, else 1.
    auto optional_float = [](ObjectReader& r) { return r.starts_value(r.peek()) ? r.parse_float() : 1.0; };
    // POV-Ray's `(int)Parse_Float()` switches: a value truncated towards zero, non-zero meaning on.
    auto read_switch = [](ObjectReader& r) {
        return static_cast<int>(r.parse_float()) != 0 ? PhotonSwitch::On : PhotonSwitch::Off;
    };
    // POV-Ray's CheckPassThru: target, pass_through and refraction cannot all be on; the one turned off depends
    // on which was set last.
    // Each item applies to every part of the object (a union flattened into its parts keeps each part's own
    // flags but those the block sets), then CheckPassThru runs on each, warning once per item.
    bool warned = false;
    auto check_pass_through = [&warned](ObjectReader& r, ObjectPhotons& ph, const Token& at, std::string_view last) {
        if (!(ph.pass_through && ph.target && ph.refraction != PhotonSwitch::Off)) return;
        const bool drop_pass_through = last == "refraction" || (last == "target" && ph.refraction == PhotonSwitch::On);
        if (!warned)
            r.warn(at, drop_pass_through ? "Cannot use pass_through with refraction & target.\nTurning off pass_through."
                                         : "Cannot use pass_through with refraction & target.\nTurning off refraction.");
        warned = true;
        if (drop_pass_through) ph.pass_through = false;
        else ph.refraction = PhotonSwitch::Off;
    };
    auto each = [&ov](auto&& apply) {
        for (ObjectPart& part : ov.parts) apply(part.object.photons);
    };
    r.expect("{");
    while (!r.accept("}")) {
        const Token t = r.next();
        warned = false;
        if (r.is_word(t, "target")) {
            const double multiplier = optional_float(r);
            each([&](ObjectPhotons& ph) {
                ph.spacing_multiplier = multiplier;
                ph.target = multiplier > 0.0;
                if (ph.target) check_pass_through(r, ph, t, "target");
            });
        } else if (r.is_word(t, "refraction")) {
            const PhotonSwitch v = read_switch(r);
            each([&](ObjectPhotons& ph) {
                ph.refraction = v;
                if (v == PhotonSwitch::On) check_pass_through(r, ph, t, "refraction");
            });
        } else if (r.is_word(t, "reflection")) {
            const PhotonSwitch v = read_switch(r);
            each([&](ObjectPhotons& ph) { ph.reflection = v; });
        } else if (r.is_word(t, "pass_through")) {
            const bool on = static_cast<int>(optional_float(r)) != 0;
            each([&](ObjectPhotons& ph) {
                ph.pass_through = on;
                if (on) check_pass_through(r, ph, t, "pass_through");
            });
        } else if (r.is_word(t, "collect")) {
            const bool on = optional_float(r) > 0.0;
            each([&](ObjectPhotons& ph) { ph.collect = on; });
        } else {
            r.fail(t, "expected target, refraction, reflection, pass_through or collect in photons but found " +
                          describe_token(t));
        }
    }
}

void ObjectReader::read_light_photons(ObjectReader& r, Light& light, const Token&) {
    auto read_switch = [](ObjectReader& r) {
        return static_cast<int>(r.parse_float()) != 0 ? PhotonSwitch::On : PhotonSwitch::Off;
    };
    r.expect("{");
    while (!r.accept("}")) {
        const Token t = r.next();
        if (r.is_word(t, "refraction")) light.photon_refraction = read_switch(r);
        else if (r.is_word(t, "reflection")) light.photon_reflection = read_switch(r);
        else if (r.is_word(t, "area_light")) light.photon_area_light = true;
        else r.fail(t, "expected refraction, reflection or area_light in photons but found " + describe_token(t));
    }
}

void SceneReader::parse_photons(const Token& kw, PhotonSettings& ph) {
    // POV-Ray compat: every photons block starts again from the defaults.
    ph = PhotonSettings{};
    ph.loc = make_diagnostic(Severity::Note, kw, "").loc;
    expect("{");
    while (!accept("}")) {
        const Token t = next();
        const std::string w(t.text.view());
        if (w == "spacing") {
            ph.spacing = parse_float();
        } else if (w == "count") {
            ph.count = static_cast<int>(parse_float());
        } else if (w == "gather") {
            ph.gather_min = static_cast<int>(parse_float());
            accept(",");
            ph.gather_max = static_cast<int>(parse_float());
        } else if (w == "media") {
            ph.media_steps = static_cast<int>(parse_float());
            if (ph.media_steps < 0) fail(t, "max media steps must be non-negative.");
            accept(",");
            ph.media_factor = starts_value(peek()) ? parse_float() : 1.0;
            if (ph.media_factor <= 0.0) fail(t, "media spacing factor must be greater than zero.");
        } else if (w == "jitter") {
            ph.jitter = parse_float();
        } else if (w == "max_trace_level") {
            ph.max_trace_level = static_cast<int>(parse_float());
        } else if (w == "adc_bailout") {
            ph.adc_bailout = parse_float();
        } else if (w == "autostop") {
            ph.autostop = parse_float();
        } else if (w == "expand_thresholds") {
            ph.expand_tolerance = parse_float();
            accept(",");
            ph.expand_min = static_cast<int>(parse_float());
            if (ph.expand_tolerance < 0.0) {
                warn(t, "The first parameter of expand_thresholds must be greater than or equal to 0.\nSetting it "
                        "to 0 now.");
                ph.expand_tolerance = 0.0;
            }
            if (ph.expand_min < 0) {
                warn(t, "The second parameter of expand_thresholds must be greater than or equal to 0.\nSetting it "
                        "to 0 now.");
                ph.expand_min = 0;
            }
        } else if (w == "radius") {
            // radius [gather [, multiplier [, media gather [, media multiplier]]]], each optional.
            double* slots[] = {&ph.radius, &ph.radius_multiplier, &ph.media_radius, &ph.media_radius_multiplier};
            const double defaults[] = {-1.0, 1.0, -1.0, 1.0};
            for (int i = 0; i < 4; ++i) {
                *slots[i] = starts_value(peek()) ? parse_float() : defaults[i];
                if (i < 3 && !accept(",")) break;
            }
        } else if (w == "save_file" || w == "load_file") {
            const bool load = w == "load_file";
            if (!ph.file.empty())
                warn(t, ph.load == load ? "Filename already given, using new name"
                                        : std::string("Cannot both load and save photon map. Now switching to ") +
                                              (load ? "load" : "save") + " mode.");
            const Token name_tok = peek();
            // Kept as found from the scene's folder, where the render reads or writes it (app/photon_file_io.cpp).
            ph.file = scene_relative(parse_string()).string();
            ph.load = load;
            if (load) require_readable(name_tok, ph.file, "photons load_file");
            else require_writable(name_tok, ph.file);
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected a photons setting but found '" + w + "'");
        }
    }
    if (ph.gather_max > 0) {
        if (ph.gather_min < 0) fail(kw, "min_gather_count cannot be negative.");
        if (ph.gather_min > ph.gather_max) fail(kw, "min_gather_count must be less than max_gather_count.");
    }
}

}  // namespace wardray::parser
