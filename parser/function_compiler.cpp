// User functions: compiling `function { ... }` bodies to FunctionProgram and calling them at parse time.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "function/internal_functions.h"
#include "parser/keywords.h"
#include "parser/parser.h"
#include "parser/pattern_functions.h"

namespace wardray::parser {

namespace {

struct NamedFn1 {
    const char* name;
    MathFn1 fn;
};

constexpr NamedFn1 k_math1[] = {
    {"abs", MathFn1::Abs},     {"ceil", MathFn1::Ceil},   {"floor", MathFn1::Floor},  {"int", MathFn1::Int},
    {"sqrt", MathFn1::Sqrt},   {"sin", MathFn1::Sin},     {"cos", MathFn1::Cos},      {"tan", MathFn1::Tan},
    {"asin", MathFn1::Asin},   {"acos", MathFn1::Acos},   {"sinh", MathFn1::Sinh},    {"cosh", MathFn1::Cosh},
    {"tanh", MathFn1::Tanh},   {"asinh", MathFn1::Asinh}, {"acosh", MathFn1::Acosh},  {"atanh", MathFn1::Atanh},
    {"exp", MathFn1::Exp},     {"ln", MathFn1::Ln},       {"log", MathFn1::Log},      {"radians", MathFn1::Radians},
    {"degrees", MathFn1::Degrees}};

struct NamedFn2 {
    const char* name;
    MathFn2 fn;
};

constexpr NamedFn2 k_math2[] = {{"atan2", MathFn2::Atan2}, {"pow", MathFn2::Pow}, {"mod", MathFn2::Mod},
                                {"div", MathFn2::Div}};

Instruction op(Instruction::Op o, std::uint32_t a = 0) {
    Instruction ins;
    ins.op = o;
    ins.a = a;
    return ins;
}

}  // namespace

/// Recursive-descent compiler of a function body, reading tokens through the parser (so macros and directives
/// inside the body work) and emitting stack-machine code.
class FunctionCompiler {
public:
    FunctionCompiler(Evaluator& evaluator, FunctionProgram& program) : m_p(evaluator), m_prog(program) {}

    /// `?:`, the lowest precedence level.
    void expression() {
        logical();
        if (!m_p.is_punct(m_p.peek(), "?")) return;
        m_p.next();
        const std::size_t to_else = m_prog.emit(op(Instruction::Op::JumpIfZero));
        expression();
        const std::size_t to_end = m_prog.emit(op(Instruction::Op::Jump));
        m_p.expect(":");
        m_prog.patch_jump(to_else, m_prog.size());
        expression();
        m_prog.adjust_depth(-1);  // only one branch's value is on the stack
        m_prog.patch_jump(to_end, m_prog.size());
    }

private:
    void logical() {
        relational();
        while (true) {
            const Token& t = m_p.peek();
            if (!m_p.is_punct(t, "&") && !m_p.is_punct(t, "|")) return;
            const bool is_and = t.text == "&";
            m_p.next();
            relational();
            m_prog.emit(op(is_and ? Instruction::Op::And : Instruction::Op::Or));
        }
    }

    void relational() {
        using Op = Instruction::Op;
        additive();
        while (true) {
            const Token& t = m_p.peek();
            if (t.kind != TokenKind::Punct) return;
            Op o;
            if (t.text == "<") o = Op::Lt;
            else if (t.text == "<=") o = Op::Le;
            else if (t.text == "=") o = Op::Eq;
            else if (t.text == "!=") o = Op::Ne;
            else if (t.text == ">=") o = Op::Ge;
            else if (t.text == ">") o = Op::Gt;
            else return;
            m_p.next();
            additive();
            m_prog.emit(op(o));
        }
    }

    void additive() {
        multiplicative();
        while (true) {
            const Token& t = m_p.peek();
            if (!m_p.is_punct(t, "+") && !m_p.is_punct(t, "-")) return;
            const bool plus = t.text == "+";
            m_p.next();
            multiplicative();
            m_prog.emit(op(plus ? Instruction::Op::Add : Instruction::Op::Sub));
        }
    }

    void multiplicative() {
        unary();
        while (true) {
            const Token& t = m_p.peek();
            if (!m_p.is_punct(t, "*") && !m_p.is_punct(t, "/")) return;
            const bool mul = t.text == "*";
            m_p.next();
            unary();
            m_prog.emit(op(mul ? Instruction::Op::Mul : Instruction::Op::Div));
        }
    }

    void unary() {
        const Token t = m_p.peek();
        const SourceStream::NestingGuard guard(m_p, t);
        if (m_p.is_punct(t, "-")) {
            m_p.next();
            unary();
            m_prog.emit(op(Instruction::Op::Neg));
        } else if (m_p.is_punct(t, "+")) {
            m_p.next();
            unary();
        } else if (m_p.is_punct(t, "!")) {
            m_p.next();
            unary();
            m_prog.emit(op(Instruction::Op::Not));
        } else {
            primary();
        }
    }

    void constant(double v) {
        Instruction ins = op(Instruction::Op::Const);
        ins.value = v;
        m_prog.emit(ins);
    }

    /// `( a, b, ... )`, each compiled onto the stack; returns how many.
    std::uint32_t arguments() {
        m_p.expect("(");
        std::uint32_t n = 0;
        if (m_p.accept(")")) return 0;
        do {
            expression();
            ++n;
        } while (m_p.accept(","));
        m_p.expect(")");
        return n;
    }

    void expect_count(const Token& name, std::uint32_t got, std::uint32_t min, std::uint32_t max) {
        if (got >= min && got <= max) return;
        const std::string want = min == max ? std::to_string(min) : std::to_string(min) + " to " + std::to_string(max);
        m_p.fail(name, "'" + name.text + "' takes " + want + " argument(s) but " + std::to_string(got) +
                           " were given");
    }

    /// A float constant read from a declared identifier, with an optional `.x`-style item for vectors.
    void declared_numeric(const Token& t, Numeric n) {
        if (m_p.is_punct(m_p.peek(), ".")) n = m_p.parse_postfix(&n);
        if (n.n != 1) m_p.fail(t, "'" + t.text + "' is a vector; a function body needs a float here");
        constant(n.v[0]);
    }

    void call_user(const Token& t, const UserFunction& f) {
        const std::uint32_t n = arguments();
        switch (f.kind) {
            case UserFunction::Kind::Float: {
                const FunctionProgram& callee = *f.program;
                if (callee.unsupported().empty() && n != callee.arity())
                    expect_count(t, n, static_cast<std::uint32_t>(callee.arity()),
                                 static_cast<std::uint32_t>(callee.arity()));
                m_prog.emit_call(f.program, n);
                return;
            }
            case UserFunction::Kind::Pattern:
                if (!m_p.m_options.pattern_value) {
                    m_prog.emit_unsupported(n, "pattern function is not rendered yet");
                    return;
                }
                m_prog.emit_external(make_pattern_function(f.pigment, m_p.m_options), n);
                return;
            case UserFunction::Kind::Pigment: {
                // POV-Ray compat: a pigment function gives a float through one of its colour's items.
                if (!m_p.is_punct(m_p.peek(), ".") || !m_p.m_options.pigment_value) break;
                m_p.next();
                const Token item = m_p.expect_identifier();
                const int channel = pigment_channel(item.text.view());
                if (channel < 0) m_p.fail(item, "unknown dot item '." + item.text + "' of a pigment function");
                m_prog.emit_external(make_pigment_channel(f.pigment, channel, m_p.m_options), n);
                return;
            }
            case UserFunction::Kind::Spline: {
                // A component of the spline's value (`S(t).y`); a call without one is read and flagged: the
                // function then evaluates it to 0 and its user warns.
                if (m_p.accept(".")) {
                    const Token item = m_p.expect_identifier();
                    const int channel = pigment_channel(item.text.view());
                    if (channel < 0 || channel > 4)
                        m_p.fail(item, "unknown dot item '." + item.text + "' of a spline function");
                    m_prog.emit_external(make_spline_channel(f.spline, channel), n);
                    return;
                }
                m_prog.emit_unsupported(n, "a spline function called inside a function without a component (.x, .y, ...) is not rendered yet");
                return;
            }
            default:
                break;
        }
        m_p.fail(t, "'" + t.text + "' returns a vector or colour; only float functions and pigment functions "
                                   "with an item such as .red can be called inside a function");
    }

    void primary() {
        const Token t = m_p.peek();
        if (t.kind == TokenKind::Number) {
            m_p.next();
            constant(t.number());
            return;
        }
        if (m_p.is_punct(t, "(")) {
            m_p.next();
            expression();
            m_p.expect(")");
            return;
        }
        if (t.kind != TokenKind::Identifier)
            m_p.fail(t, "expected a float expression in the function body but found " + describe_token(t));
        const TokenText& w = t.text;
        // Loop variables of sum() and prod(), innermost first, then parameters, shadow everything else.
        for (auto it = m_loop_vars.rbegin(); it != m_loop_vars.rend(); ++it) {
            if (it->name != w) continue;
            m_p.next();
            m_prog.emit(op(Instruction::Op::Local, it->slot));
            return;
        }
        const auto& params = m_prog.params();
        // POV-Ray compat: u and v read the x and y arguments (the parameters of a parametric's functions).
        const std::string_view alias = w == "u" ? "x" : w == "v" ? "y" : "";
        for (std::size_t i = 0; i < params.size(); ++i) {
            if (params[i] != w && (alias.empty() || params[i] != alias)) continue;
            m_p.next();
            m_prog.emit(op(Instruction::Op::Arg, static_cast<std::uint32_t>(i)));
            return;
        }
        if (const auto m = m_p.m_macros.find(w); m != m_p.m_macros.end()) {
            m_p.next();
            m_p.invoke_macro(t, m->second);
            primary();
            return;
        }
        if (m_p.is_array_element_next()) {
            const Value element = *m_p.take_array_element();
            // POV-Ray compat: an element of an array of functions is called like a declared function.
            if (const auto* f = std::get_if<std::shared_ptr<const UserFunction>>(&element)) {
                const std::shared_ptr<const UserFunction> keep = *f;
                call_user(t, *keep);
                return;
            }
            const auto* n = std::get_if<Numeric>(&element);
            if (n == nullptr) m_p.fail(t, "this element of '" + w + "' is neither a float nor a function");
            declared_numeric(t, *n);
            return;
        }
        if (const Value* v = m_p.lookup(w)) {
            m_p.next();
            if (const auto* f = std::get_if<std::shared_ptr<const UserFunction>>(v)) {
                const std::shared_ptr<const UserFunction> keep = *f;
                call_user(t, *keep);
                return;
            }
            if (const auto* n = std::get_if<Numeric>(v)) {
                declared_numeric(t, *n);
                return;
            }
            m_p.fail(t, "'" + w + "' is " + value_kind_name(*v) + "; a function body needs a float here");
        }
        if (w == "sum" || w == "prod") {
            m_p.next();
            sequence(t);
            return;
        }
        for (const auto& [name, fn] : k_math1) {
            if (w != name) continue;
            m_p.next();
            expect_count(t, arguments(), 1, 1);
            m_prog.emit(op(Instruction::Op::Call1, static_cast<std::uint32_t>(fn)));
            return;
        }
        for (const auto& [name, fn] : k_math2) {
            if (w != name) continue;
            m_p.next();
            expect_count(t, arguments(), 2, 2);
            m_prog.emit(op(Instruction::Op::Call2, static_cast<std::uint32_t>(fn)));
            return;
        }
        if (w == "atan") {
            m_p.next();
            const std::uint32_t n = arguments();
            expect_count(t, n, 1, 2);
            if (n == 1) m_prog.emit(op(Instruction::Op::Call1, static_cast<std::uint32_t>(MathFn1::Atan)));
            else m_prog.emit(op(Instruction::Op::Call2, static_cast<std::uint32_t>(MathFn2::Atan2)));
            return;
        }
        if (w == "min" || w == "max") {
            m_p.next();
            const std::uint32_t n = arguments();
            expect_count(t, n, 1, 256);
            const auto fn = static_cast<std::uint32_t>(w == "min" ? MathFn2::Min : MathFn2::Max);
            for (std::uint32_t i = 1; i < n; ++i) m_prog.emit(op(Instruction::Op::Call2, fn));
            return;
        }
        if (w == "select") {
            m_p.next();
            const std::uint32_t n = arguments();
            expect_count(t, n, 3, 4);
            m_prog.emit(op(n == 3 ? Instruction::Op::Select3 : Instruction::Op::Select4));
            return;
        }
        if (auto c = m_p.builtin_constant(t)) {
            m_p.next();
            declared_numeric(t, *c);
            return;
        }
        if (is_keyword(w)) m_p.fail(t, "'" + w + "' cannot be used in a function body");
        m_p.fail_undeclared(t);
    }

    /// `sum(I, A, B, E)` or `prod(I, A, B, E)` after its name: E added (multiplied) up for I = A, A + 1, ...
    /// while I <= B, starting from 0 (1). The counter and the limit live in two local slots.
    void sequence(const Token& name) {
        using Op = Instruction::Op;
        m_p.expect("(");
        if (m_p.is_punct(m_p.peek(), ")")) expect_count(name, 0, 4, 4);
        const Token var = loop_variable(name);
        const std::uint32_t slot = m_slots_in_use;
        m_slots_in_use += 2;
        m_prog.require_locals(m_slots_in_use);
        // POV-Ray compat: the last value already sees the variable, holding the first value. The first value
        // does not see it here (POV-Ray reads an unset slot there).
        sequence_comma(name, 1);
        expression();
        m_prog.emit(op(Op::StoreLocal, slot));
        sequence_comma(name, 2);
        // POV-Ray compat: x, y, z, u and v always read the function's arguments, so such a loop variable is
        // never seen.
        const bool visible = !is_argument_register(var.text);
        if (visible) m_loop_vars.push_back({var.text, slot});
        expression();
        m_prog.emit(op(Op::StoreLocal, slot + 1));
        sequence_comma(name, 3);
        // The running result stays on the operand stack; each pass combines E's value into it.
        constant(name.text == "sum" ? 0.0 : 1.0);
        Instruction test = op(Op::LoopTest);
        test.b = slot;
        const std::size_t skip = m_prog.emit(test);
        Instruction next = op(Op::LoopNext, static_cast<std::uint32_t>(m_prog.size()));
        next.b = slot;
        expression();
        m_prog.emit(op(name.text == "sum" ? Op::Add : Op::Mul));
        m_prog.emit(next);
        m_prog.patch_jump(skip, m_prog.size());
        if (m_p.is_punct(m_p.peek(), ",")) {
            // Count the extra arguments, so the message says how many there were.
            std::uint32_t got = 4;
            while (m_p.accept(",")) {
                expression();
                ++got;
            }
            m_p.expect(")");
            expect_count(name, got, 4, 4);
        }
        m_p.expect(")");
        if (visible) m_loop_vars.pop_back();
        m_slots_in_use -= 2;
    }

    /// The `,` after argument `got` of sum()/prod(); a `)` there is a wrong argument count.
    void sequence_comma(const Token& name, std::uint32_t got) {
        if (m_p.is_punct(m_p.peek(), ")")) expect_count(name, got, 4, 4);
        m_p.expect(",");
    }

    static bool is_argument_register(std::string_view w) {
        return w == "x" || w == "y" || w == "z" || w == "u" || w == "v";
    }

    /// Reads the loop variable of sum()/prod(): a name that is new, a parameter or an enclosing loop variable.
    Token loop_variable(const Token& name) {
        const Token var = m_p.peek();
        const std::string what = "the loop variable of '" + std::string(name.text) + "'";
        if (var.kind != TokenKind::Identifier)
            m_p.fail(var, what + " must be a name, but found " + describe_token(var));
        const std::string w = var.text;
        m_p.next();
        if (is_argument_register(w)) {
            m_p.warn(var, "'" + w + "' inside '" + std::string(name.text) + "' still reads the function's " + w +
                              " argument (as in POV-Ray), so " + what + " is never read; choose another name");
            return var;
        }
        const auto& params = m_prog.params();
        const bool shadows = std::find(params.begin(), params.end(), w) != params.end() ||
                             std::any_of(m_loop_vars.begin(), m_loop_vars.end(),
                                         [&](const LoopVariable& l) { return l.name == w; });
        if (shadows) return var;
        if (is_keyword(w)) m_p.fail(var, "'" + w + "' is a reserved word; " + what + " needs a new name");
        if (m_p.find_slot(w) != nullptr || m_p.m_macros.count(w) > 0)
            m_p.fail(var, "'" + w + "' is already declared; " + what + " needs a new name");
        return var;
    }

    struct LoopVariable {
        std::string name;
        std::uint32_t slot = 0;  ///< the counter's local slot; the limit is in the next one
    };

    Evaluator& m_p;
    FunctionProgram& m_prog;
    std::vector<LoopVariable> m_loop_vars;  ///< loop variables in scope, innermost last
    std::uint32_t m_slots_in_use = 0;      ///< local slots taken by the enclosing sum()/prod() calls
};

std::shared_ptr<const UserFunction> Evaluator::parse_user_function(const Token& kw) {
    auto f = std::make_shared<UserFunction>();
    f->loc = make_diagnostic(Severity::Note, kw, "").loc;
    std::vector<std::string> params;
    if (accept("(")) {
        if (!accept(")")) {
            do {
                params.push_back(expect_identifier().text);
            } while (accept(","));
            expect(")");
        }
    } else {
        params = {"x", "y", "z"};
    }
    expect("{");
    // POV-Ray compat: a macro may stand for the whole body, `function { M() }` with M giving `pigment { ... }`.
    expand_macros();
    const Token first = peek();
    if (is_word(first, "internal")) {
        // POV-Ray compat: the built-in functions of functions.inc; accepted, evaluated only when implemented.
        next();
        expect("(");
        const Token number = peek();
        const double n = parse_float();
        expect(")");
        expect("}");
        const int index = static_cast<int>(n);
        const std::size_t arity = internal_function_arity(index);
        if (arity == 0 || index != n) fail(number, "there is no internal function " + number.text);
        // x, y, z and the function's own parameters, as POV-Ray counts them.
        params = {"x", "y", "z"};
        for (std::size_t i = 3; i < arity; ++i) {
            std::string name = "P";
            name += std::to_string(i - 3);
            params.push_back(std::move(name));
        }
        auto program = std::make_shared<FunctionProgram>(params);
        for (std::uint32_t i = 0; i < arity; ++i) program->emit({Instruction::Op::Arg, i, 0, 0.0});
        if (internal_function(index) != nullptr)
            program->emit({Instruction::Op::Internal, static_cast<std::uint32_t>(index),
                           static_cast<std::uint32_t>(arity), 0.0});
        else
            program->emit_unsupported(static_cast<std::uint32_t>(arity),
                                      "internal function " + std::to_string(index) + " is not supported yet");
        f->program = std::move(program);
        return f;
    }
    if (is_word(first, "spline")) {
        f->kind = UserFunction::Kind::Spline;
        f->spline = std::make_shared<const Spline>(parse_spline_body(next()));
        expect("}");
        return f;
    }
    if (is_word(first, "pattern") || is_word(first, "pigment")) {
        const Token block = next();
        f->kind = first.text == "pattern" ? UserFunction::Kind::Pattern : UserFunction::Kind::Pigment;
        f->pigment = std::make_shared<const Pigment>(parse_function_pigment(block));
        expect("}");
        return f;
    }
    if (is_word(first, "transform")) {
        f->kind = UserFunction::Kind::Transform;
        f->transform = parse_transform_body(next());
        expect("}");
        return f;
    }
    auto program = std::make_shared<FunctionProgram>(std::move(params));
    FunctionCompiler compiler(*this, *program);
    compiler.expression();
    expect("}");
    f->program = std::move(program);
    return f;
}

Numeric Evaluator::call_user_function(const Token& name, const UserFunction& f) {
    expect("(");
    std::vector<double> args;
    if (!accept(")")) {
        do {
            const Token at = peek();
            const Numeric a = parse_conditional(true);
            if (a.n != 1) fail(at, "function arguments must be floats");
            args.push_back(a.v[0]);
        } while (accept(","));
        expect(")");
    }
    const std::string what = "'" + name.text + "'";
    switch (f.kind) {
        case UserFunction::Kind::Float: {
            const FunctionProgram& program = *f.program;
            const std::string& reason = program.unsupported();
            if (reason.rfind("internal", 0) == 0) fail(name, reason + " (called through " + what + ")");
            if (!reason.empty()) warn_once(name, reason + " (" + what + " evaluates to 0)");
            else if (args.size() != program.arity())
                fail(name, what + " takes " + std::to_string(program.arity()) + " argument(s) but " +
                               std::to_string(args.size()) + " were given");
            return Numeric::scalar(program.evaluate(args, EvalContext{scene_noise_generator()}));
        }
        case UserFunction::Kind::Transform: {
            args.resize(3, 0.0);
            return Numeric::vector3(f.transform.point({args[0], args[1], args[2]}));
        }
        case UserFunction::Kind::Pattern: {
            if (!m_options.pattern_value) {
                warn_once(name, "pattern function is not rendered yet (" + what + " evaluates to 0)");
                return Numeric::scalar(0.0);
            }
            args.resize(std::max<std::size_t>(args.size(), 3), 0.0);
            return Numeric::scalar(
                m_options.pattern_value(f.pigment->pattern, {args[0], args[1], args[2]}, scene_noise_generator()));
        }
        case UserFunction::Kind::Pigment:
            if (!m_options.pigment_value) {
                warn_once(name, "pigment function is not rendered yet (" + what + " evaluates to black)");
                return Numeric::color(Color{});
            }
            args.resize(std::max<std::size_t>(args.size(), 3), 0.0);
            return Numeric::color(
                m_options.pigment_value(*f.pigment, {args[0], args[1], args[2]}, scene_noise_generator()));
        case UserFunction::Kind::Spline:
            if (args.size() != 1) fail(name, what + " is a spline function: it takes 1 argument");
            return spline_value(*f.spline, f.spline->type, args[0]);
    }
    return Numeric::scalar(0.0);
}

}  // namespace wardray::parser
