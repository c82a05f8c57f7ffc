// Light groups: `light_group { objects light_sources [global_lights] transforms }`, a union whose own lights light
// only its own objects, as POV-Ray 3.7 reads it (Parse_Light_Group, Promote_Local_Lights).
#include <map>

#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

/// Gives a surface and its CSG children the group's lights; a surface already in a nested group keeps only that
/// group's (POV-Ray's Promote_Local_Lights_Recursive stops at a child that has lights of its own).
void join_group(Object& o, int group) {
    if (!o.light_groups.empty()) return;
    o.light_groups.push_back(group);
    if (auto* csg = std::get_if<Csg>(&o.shape))
        for (Object& child : csg->children) join_group(child, group);
}

/// POV-Ray's Set_CSG_Children_Flag for NO_GLOBAL_LIGHTS_FLAG: down the tree, except where a nested group set it.
void set_no_global_lights(Object& o, bool off) {
    o.no_global_lights = off;
    if (auto* csg = std::get_if<Csg>(&o.shape))
        for (Object& child : csg->children) set_no_global_lights(child, off);
}

void renumber(Object& o, std::map<int, int>& numbers, int& count) {
    for (int& g : o.light_groups) {
        auto [it, added] = numbers.try_emplace(g, 0);
        if (added) it->second = ++count;
        g = it->second;
    }
    if (auto* csg = std::get_if<Csg>(&o.shape))
        for (Object& child : csg->children) renumber(child, numbers, count);
}

}  // namespace

ObjectValue ObjectReader::parse_light_group(const Token& /*kw*/) {
    expect("{");
    const int group = ++m_light_group_count;
    ObjectValue ov;
    ov.compound = true;
    std::vector<std::size_t> grouped;  // the parts that came from nested light groups
    bool any_light = false;
    while (true) {
        expand_macros();
        const Token& t = peek();
        if (is_word(t, "light_source")) {
            // Only the group's own light sources are local; lights inside its objects stay global.
            const Token lkw = next();
            ObjectValue looks;
            Light light = parse_light_body(lkw, &looks);
            for (ObjectPart& part : looks.parts) ov.parts.push_back(std::move(part));
            light.group = group;
            ov.lights.push_back(std::move(light));
            any_light = true;
        } else if (is_object_start(t)) {
            const Token child_kw = next();
            const bool nested = is_word(child_kw, "light_group");
            ObjectValue child = parse_object(child_kw);
            const scene::Cow<Texture> child_texture =
                child.texture ? scene::Cow<Texture>(*child.texture) : scene::Cow<Texture>();
            for (ObjectPart& part : child.parts) {
                if (!part.has_texture && child.texture) {
                    part.object.texture = child_texture;  // one value the untextured parts share
                    part.has_texture = true;
                }
                if (nested) grouped.push_back(ov.parts.size());
                ov.parts.push_back(std::move(part));
            }
            for (Light& l : child.lights) ov.lights.push_back(std::move(l));
        } else {
            break;
        }
    }
    // POV-Ray compat: a group without lights or without objects is a plain union (whose objects still see no
    // global lights unless it says global_lights).
    if (any_light)
        for (ObjectPart& part : ov.parts) join_group(part.object, group);
    bool global_lights = false;
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (parse_transform_item(t, tr)) {
            apply_transform(ov, tr);
            continue;
        }
        next();
        if (is_punct(t, "}")) break;
        if (is_word(t, "global_lights")) {
            global_lights = parse_bool_optional();
        } else if (is_word(t, "photons")) {
            warn_unsupported(t, "light_group photons");
            skip_block(t);
        } else {
            fail(t, "expected global_lights, a transform or '}' in light_group but found " + describe_token(t));
        }
    }
    std::size_t next_nested = 0;
    for (std::size_t i = 0; i < ov.parts.size(); ++i) {
        if (next_nested < grouped.size() && grouped[next_nested] == i) {
            ++next_nested;
            continue;
        }
        set_no_global_lights(ov.parts[i].object, !global_lights);
    }
    return ov;
}

void ObjectReader::renumber_light_groups(ObjectValue& ov) {
    std::map<int, int> numbers;
    for (Light& l : ov.lights) {
        if (l.group == 0) continue;
        auto [it, added] = numbers.try_emplace(l.group, 0);
        if (added) it->second = ++m_light_group_count;
        l.group = it->second;
    }
    for (ObjectPart& part : ov.parts) renumber(part.object, numbers, m_light_group_count);
}

}  // namespace wardray::parser
