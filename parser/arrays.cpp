// Arrays: `array[N][M] { ... }` declarations, element access and element assignment.
#include <cmath>

#include "parser/parser.h"

namespace wardray::parser {

Value Evaluator::parse_array_declaration(const Token& kw) {
    auto array = std::make_shared<ArrayValue>();
    std::size_t total = 1;
    while (is_punct(peek_expr(), "[")) {
        next();
        const Token at = peek();
        const double n = parse_float();
        expect("]");
        if (!(n >= 1.0)) fail(at, "array size must be at least 1");
        if (n > static_cast<double>(m_options.max_array_elements) ||
            static_cast<double>(total) * n > static_cast<double>(m_options.max_array_elements))
            fail(at, "array has more elements than the limit of " + std::to_string(m_options.max_array_elements) +
                         "; raise it with --max-array-size");
        array->dims.push_back(static_cast<std::size_t>(n));
        total *= array->dims.back();
    }
    if (array->dims.empty()) fail(kw, "expected '[' after 'array'");
    // A large array is checked against the memory budget before it is allocated: a macro recursion holding
    // one at each level would otherwise take gigabytes between two of the token stream's checks.
    if (total >= 4096) check_memory(kw, total * sizeof(Value));
    array->elements.resize(total);
    if (is_punct(peek_expr(), "{")) parse_array_initializer(*array, 0, 0, kw);
    return array;
}

void Evaluator::parse_array_initializer(ArrayValue& array, std::size_t dim, std::size_t offset, const Token& kw) {
    const NestingGuard guard(*this, kw);
    const Token open = expect("{");
    std::size_t stride = 1;
    for (std::size_t d = dim + 1; d < array.dims.size(); ++d) stride *= array.dims[d];
    std::size_t i = 0;
    while (!is_punct(peek(), "}")) {
        if (i >= array.dims[dim]) fail(peek(), "too many elements in array initializer");
        if (dim + 1 < array.dims.size()) {
            parse_array_initializer(array, dim + 1, offset + i * stride, kw);
        } else {
            array.elements[offset + i] = parse_rvalue();
        }
        ++i;
        accept(",");  // POV-Ray compat: the commas between elements are optional
    }
    expect("}");
    if (i != array.dims[dim])
        fail(open, "array initializer has " + std::to_string(i) + " elements but the array needs " +
                       std::to_string(array.dims[dim]));
}

std::size_t Evaluator::parse_array_index(const ArrayValue& array, const Token& id) {
    std::size_t flat = 0;
    for (std::size_t d = 0; d < array.dims.size(); ++d) {
        expect("[");
        const Token at = peek();
        const double f = parse_float();
        expect("]");
        const double index = std::trunc(f);
        if (!(index >= 0.0) || index >= static_cast<double>(array.dims[d]))
            fail(at, "index " + std::to_string(static_cast<long long>(index)) + " of '" + id.text +
                         "' is out of range (size " + std::to_string(array.dims[d]) + ")");
        flat = flat * array.dims[d] + static_cast<std::size_t>(index);
        if (d + 1 < array.dims.size() && !is_punct(peek_expr(), "["))
            fail(peek(), "'" + id.text + "' needs " + std::to_string(array.dims.size()) + " indices");
    }
    return flat;
}

bool Evaluator::is_array_element_next() {
    const Token& t = peek();
    if (t.kind != TokenKind::Identifier) return false;
    const Value* v = lookup(t.text);
    if (v == nullptr || !std::holds_alternative<std::shared_ptr<ArrayValue>>(*v)) return false;
    return is_punct(m_files[m_file]->tokens[m_pos + 1], "[");
}

std::optional<Value> Evaluator::take_array_element() {
    if (!is_array_element_next()) return std::nullopt;
    const Token id = next();
    // Keep the array alive while its index is evaluated (the index may redeclare it).
    const std::shared_ptr<ArrayValue> array = std::get<std::shared_ptr<ArrayValue>>(*lookup(id.text));
    const std::size_t index = parse_array_index(*array, id);
    if (!array->elements[index]) fail(id, "element of array '" + id.text + "' is used before it was assigned");
    return *array->elements[index];
}

}  // namespace wardray::parser
