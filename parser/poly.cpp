// The polynomial statements cubic, poly and polynomial (quartic's reader is in shapes.cpp), as POV-Ray 3.7 reads
// them (Parse_Poly, Parse_Polynom).
#include <cmath>
#include <string>

#include "parser/parser.h"

namespace wardray::parser {

namespace {

// POV-Ray's MAX_ORDER: the highest order a poly may have.
constexpr int k_max_order = 35;

// The number of monomials of three variables of degree at most `order`.
std::size_t term_count(int order) {
    return static_cast<std::size_t>((order + 1) * (order + 2) * (order + 3) / 6);
}

}  // namespace

void Parser::parse_poly_order(Poly& p) {
    const Token at = peek();
    // POV-Ray compat: the order is truncated to a whole number.
    p.order = static_cast<int>(parse_float());
    if (p.order < 2 || p.order > k_max_order) fail(at, std::string("the order of a ") + p.keyword() + " must be 2 to 35");
    accept(",");
}

void Parser::parse_poly_coefficients(Poly& p) {
    // One vector of any length: read the terms one by one so no 5-component limit applies.
    p.coefficients.assign(term_count(p.order), 0.0);
    expect("<");
    for (std::size_t i = 0; i < p.coefficients.size(); ++i) {
        // POV-Ray compat: the commas are optional.
        if (i > 0) accept(",");
        // The additive level, as in `matrix`: a '>' here closes the vector, it is no comparison.
        const Token at = peek();
        const Numeric c = parse_additive();
        if (c.n != 1) fail(at, std::string(p.keyword()) + " coefficients must be floats");
        p.coefficients[i] = c.v[0];
    }
    expect(">");
}

Poly Parser::read_cubic(const Token& kw) {
    Poly p;
    p.kind = Poly::Kind::Cubic;
    p.order = 3;
    parse_poly_coefficients(p);
    return p;
}

Poly Parser::read_poly(const Token& kw) {
    Poly p;
    p.kind = Poly::Kind::Poly;
    parse_poly_order(p);
    parse_poly_coefficients(p);
    return p;
}

Poly Parser::read_polynomial(const Token& kw) {
    Poly p;
    p.kind = Poly::Kind::Polynomial;
    parse_poly_order(p);
    p.coefficients.assign(term_count(p.order), 0.0);
    while (is_word(peek(), "xyz")) {
        next();
        expect("(");
        const Token where = peek();
        const double x = parse_float();
        accept(",");
        const double y = parse_float();
        accept(",");
        const double z = parse_float();
        expect(")");
        expect(":");
        const double value = parse_float();
        accept(",");
        // POV-Ray compat (Set_Coeff): the exponents are truncated to whole numbers and must not exceed the order.
        const int i = static_cast<int>(x), j = static_cast<int>(y), k = static_cast<int>(z);
        if (x < 0.0 || y < 0.0 || z < 0.0 || i + j + k > p.order)
            fail(where, "the exponents of a polynomial term must be whole, at least 0 and sum to at most its order");
        // The term's index in quartic's order: descending powers of x, then of y, then of z.
        std::size_t index = 0;
        for (int a = p.order; a >= 0; --a)
            for (int b = p.order - a; b >= 0; --b)
                for (int c = p.order - a - b; c >= 0; --c, ++index)
                    if (a == i && b == j && c == k) p.coefficients[index] = value;
    }
    return p;
}

}  // namespace wardray::parser
