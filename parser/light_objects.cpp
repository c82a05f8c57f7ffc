// The objects a light source carries: `looks_like` (an object drawn where the light is) and `projected_through`
// (the object the light shines through), as POV-Ray 3.7 reads them (Parse_Light_Source).
#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

void ObjectReader::read_looks_like(const Light& light, ObjectValue* looks, const Token& kw) {
    expect("{");
    expand_macros();
    const Token t = next();
    if (!is_object_start(t)) fail(t, "expected an object in looks_like but found " + describe_token(t));
    // POV-Ray compat (Parse_Light_Source): the object is moved to the light's position, then the modifiers after
    // it apply; it casts no shadow, and later transforms of the light move it too.
    ObjectValue object = parse_object(t);
    apply_transform(object, Transform::translation(light.position));
    parse_object_modifiers(object, object.compound);
    for (ObjectPart& part : object.parts) part.object.no_shadow = true;
    if (looks == nullptr) {
        warn_unsupported(kw, "looks_like here");
        return;
    }
    if (!looks->parts.empty()) fail(kw, "Only one looks_like allowed per light_source.");
    for (ObjectPart& part : object.parts) looks->parts.push_back(std::move(part));
}

void ObjectReader::read_projected_through(Light& light, const Token& kw) {
    if (!light.projected_through.empty()) fail(kw, "Only one projected through allowed per light_source.");
    expect("{");
    expand_macros();
    const Token t = next();
    if (!is_object_start(t)) fail(t, "expected an object in projected_through but found " + describe_token(t));
    ObjectValue object = parse_object(t);
    parse_object_modifiers(object, object.compound);
    std::optional<Object> o = as_single_object(object);
    if (!o) fail(t, "projected_through needs an object with a surface");
    light.projected_through.push_back(std::move(*o));
}

void ObjectReader::transform_light(Light& light, const Transform& tr) {
    light.position = tr.point(light.position);
    light.point_at = tr.point(light.point_at);
    // An area light's square turns and scales with its light wherever the transform comes from (its own block,
    // an object { } around a declared light, or a CSG containing it), as POV-Ray's LightSource::Transform does.
    light.area_axis1 = tr.vector(light.area_axis1);
    light.area_axis2 = tr.vector(light.area_axis2);
    for (Object& through : light.projected_through) through.transform = through.transform.then(tr);
}

}  // namespace wardray::parser
