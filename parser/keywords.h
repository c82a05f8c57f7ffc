// Keyword tables: the reserved words of POV-Ray SDL and which features are parsed but not rendered yet.
#pragma once

#include <string_view>
#include <vector>

namespace wardray::parser {

/// Every reserved word the parser knows (handled or not), for "did you mean" suggestions.
const std::vector<std::string_view>& all_keywords();
/// True for reserved words (identifiers that cannot be user names).
bool is_keyword(std::string_view word);
/// True for the floats POV-Ray's front end declares before the scene (image_width, frame_number, ...): reserved here,
/// but a scene may declare them anew, as POV-Ray lets it.
bool is_predeclared_identifier(std::string_view word);
/// Object kinds that are valid POV-Ray but not drawn yet (the drawn ones are WARDRAY_SHAPES); skipped with a warning.
bool is_unsupported_object(std::string_view word);
/// Other block statements that are valid POV-Ray but not rendered yet (fog, normal, interior, ...).
bool is_unsupported_block(std::string_view word);
/// Pigment and texture pattern keywords not rendered yet (the rendered ones are WARDRAY_PATTERNS).
bool is_pattern_keyword(std::string_view word);
/// Levenshtein distance, capped: returns limit + 1 as soon as the distance exceeds `limit`.
std::size_t edit_distance(std::string_view a, std::string_view b, std::size_t limit);

}  // namespace wardray::parser
