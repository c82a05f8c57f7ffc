// The pavement pattern's modifiers (number_of_sides, number_of_tiles, pattern, exterior, interior, form), read as
// POV-Ray 3.7's Parse_Pattern reads them, and their check once the pattern's block is complete.
#include <string>

#include "parser/parser.h"

namespace wardray::parser {

bool Parser::parse_pavement_modifier(const Token& t, Pattern& pat) {
    if (t.kind != TokenKind::Identifier) return false;
    const std::string w = t.text;
    const bool own = w == "number_of_sides" || w == "number_of_tiles" || w == "pattern";
    if (pat.type != Pattern::Type::Pavement) {
        // exterior, interior and form belong to other patterns too; these three only to pavement.
        if (own) fail(t, "Keyword '" + w + "' can only be used in a pavement pattern.");
        return false;
    }
    PavementParams& pv = pat.params->pavement;
    int* field = w == "number_of_sides"   ? &pv.sides
                 : w == "number_of_tiles" ? &pv.tiles
                 : w == "pattern"         ? &pv.number
                 : w == "exterior"        ? &pv.exterior
                 : w == "interior"        ? &pv.interior
                 : w == "form"            ? &pv.form
                                          : nullptr;
    if (field == nullptr) return false;
    next();
    // POV-Ray compat: each is kept in an unsigned char.
    *field = static_cast<int>(parse_float()) & 0xFF;
    return true;
}

void Parser::check_pavement(const Token& kw, Pattern& pat) {
    if (pat.type != Pattern::Type::Pavement) return;
    PavementParams& pv = pat.params->pavement;
    // POV-Ray compat: interior and exterior wrap modulo 3, form modulo 4 for squares and 3 otherwise; the pavings
    // each tile count has (POV-Ray's tables) bound `pattern`.
    pv.interior %= 3;
    pv.exterior %= 3;
    static const int squares[] = {1, 1, 2, 5, 12, 35};
    static const int triangles[] = {1, 1, 1, 3, 4, 12};
    static const int hexagons[] = {1, 1, 3, 7, 22};
    const int* counts = nullptr;
    int max_tiles = 6;
    std::string list;
    switch (pv.sides) {
        case 4:
            counts = squares;
            list = "(1,1,2,5,12,35)";
            pv.form %= 4;
            break;
        case 6:
            counts = hexagons;
            max_tiles = 5;
            list = "(1,1,3,7,22)";
            pv.form %= 3;
            break;
        case 3:
            counts = triangles;
            list = "(1,1,1,3,4,12)";
            pv.form %= 3;
            break;
        default:
            fail(kw, "number_of_sides of pavement must be 3, 4 or 6.");
    }
    if (pv.tiles < 1 || pv.tiles > max_tiles)
        fail(kw, "number_of_tiles of pavement must be between 1 and " + std::to_string(max_tiles) + ".");
    if (pv.number < 1 || pv.number > counts[pv.tiles - 1])
        fail(kw, "pattern value for pavement is out of range. max per tile:" + list);
}

}  // namespace wardray::parser
