// Evaluator: expressions, built-in and user functions, arrays and splines, over the preprocessor's tokens.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "parser/preprocessor.h"

namespace wardray::parser {

/// A spline's value at `t` interpolated with `type`, with as many components as the spline's values have (at
/// least two), as a call `S(t)` returns it.
Numeric spline_value(const Spline& spline, Spline::Type type, double t);

/// Reads values: float, vector and colour expressions with POV-Ray's operators and built-in functions, strings,
/// arrays, splines and user functions (compiled for the function VM). Items with a block of their own
/// (pigments, objects, ...) are read by the statement readers above through parse_item_value.
class Evaluator : public Preprocessor {
protected:
    using Preprocessor::Preprocessor;

    Value parse_rvalue() final;
    Numeric parse_numeric() final;
    double parse_float() final;
    /// A vector expression (a float is promoted to all three components).
    Vec3 parse_vector();
    std::string parse_string() final;
    /// An optional boolean after a flag keyword (`hollow`, `hollow off`); true when none is given.
    bool parse_bool_optional();
    /// `?:` and below; `allow_less` is false outside parentheses, where '<' starts the next vector.
    Numeric parse_conditional(bool allow_less = true);
    /// `&` and `|`.
    Numeric parse_logical(bool allow_less);
    /// Comparisons.
    Numeric parse_relational(bool allow_less);
    /// The additive level; `first`, when given, is an operand already read (an array element).
    Numeric parse_additive(const Numeric* first = nullptr);
    /// `*` and `/`.
    Numeric parse_multiplicative(const Numeric* first = nullptr);
    /// Unary `-`, `+` and `!`.
    Numeric parse_unary(const Numeric* first = nullptr);
    /// Dot selectors (`.x`, `.red`, ...).
    Numeric parse_postfix(const Numeric* first = nullptr);
    /// Literals, identifiers, vectors, colours, calls and parenthesised expressions.
    Numeric parse_primary();
    /// A call of the built-in function `name`.
    Numeric parse_function(const Token& name);
    /// The value of a built-in constant (pi, clock, x, ...), when `t` names one.
    std::optional<Numeric> builtin_constant(const Token& t);
    /// trace(), inside(), min_extent(), max_extent() through ParseOptions::query (functions.cpp).
    Numeric parse_geometry_query(const Token& name);
    /// True for the keywords that start a colour (color, rgb, red, ...).
    bool is_color_keyword(const Token& t) const;

    /// Reads `[(params)] { body }` after the keyword `function` and compiles it.
    std::shared_ptr<const UserFunction> parse_user_function(const Token& kw);
    /// Reads the argument list of a call of `f` and evaluates it at parse time.
    Numeric call_user_function(const Token& name, const UserFunction& f);
    /// The scene's global noise_generator as read so far (2 until global_settings names one): POV-Ray's parse-time
    /// calls of pattern functions use it, as its renders do.
    virtual int scene_noise_generator() { return 2; }
    friend class FunctionCompiler;

    /// Reads `{ [S] [type] T, value ... }` after the keyword `spline`.
    Spline parse_spline_body(const Token& kw);
    /// Reads `(t [, type])` after a spline identifier and evaluates the spline.
    Numeric call_spline(const Token& name, const Spline& spline);
    /// Warns (once per message) when `type` has too few of the spline's points to interpolate as its name says.
    void warn_few_spline_points(const Token& at, const Spline& spline, Spline::Type type);

    /// Reads one transformation item when `t` starts one, composing it onto `out`; false otherwise.
    bool parse_transform_item(const Token& t, Transform& out);
    /// Reads `transform { ... }` after its keyword.
    Transform parse_transform_body(const Token& kw);

    /// Reads `array [n]... [{ ... }]` after the keyword `array`.
    Value parse_array_declaration(const Token& kw);
    /// Reads the `{ ... }` of dimension `dim` into the elements from `offset`.
    void parse_array_initializer(ArrayValue& array, std::size_t dim, std::size_t offset, const Token& kw);
    std::size_t parse_array_index(const ArrayValue& array, const Token& id) final;
    /// When an array element `A[i]...` comes next, consumes it and returns a copy of its value.
    std::optional<Value> take_array_element();
    /// True when an array identifier followed by '[' comes next.
    bool is_array_element_next();

    /// When `t` starts an item with a block of its own (pigment, object, camera, ...), reads it (the statement
    /// readers').
    virtual std::optional<Value> parse_item_value(const Token& t) = 0;
    /// A colour expression (the texture readers').
    virtual Color parse_color() = 0;
    /// The `{ ... }` block of `function { pattern { ... } }` or `function { pigment { ... } }` (the texture
    /// readers').
    virtual Pigment parse_function_pigment(const Token& kw) = 0;

    std::vector<std::uint32_t> m_rand_streams;  ///< states of the streams seed() created
    std::uint64_t m_divisions_by_zero = 0;       ///< divisions by zero so far (each warned about)
};

}  // namespace wardray::parser
