// User functions compiled to a small stack machine, so isosurfaces and patterns evaluate them without re-parsing.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace wardray::function {

/// The built-in one-argument math functions a program can call.
enum class MathFn1 : std::uint8_t {
    Abs, Ceil, Floor, Int, Sqrt, Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Asinh, Acosh, Atanh,
    Exp, Ln, Log, Radians, Degrees
};
/// The built-in two-argument math functions a program can call.
enum class MathFn2 : std::uint8_t { Atan2, Pow, Mod, Div, Min, Max };

/// What an evaluation needs from the scene besides its arguments.
struct EvalContext {
    int noise_generator = 2;  ///< the scene's global noise_generator (f_noise3d and the noise patterns)
};

/// A function the VM calls whose code lives in a layer above it: a pattern or a pigment channel, handed in by the
/// parser with the texture layer's evaluation. Immutable; evaluate() must be thread-safe.
class ExternalFunction {
public:
    virtual ~ExternalFunction() = default;
    /// The value at the arguments (x, y, z first).
    virtual double evaluate(const double* args, std::size_t nargs, const EvalContext& context) const = 0;
};

/// One stack-machine instruction; `a` is an argument index, a local slot, a count, a jump target or a table index;
/// `b` is a count or, for the loop instructions, a local slot.
struct Instruction {
    enum class Op : std::uint8_t {
        Const,       ///< push `value`
        Arg,         ///< push argument `a`
        Add, Sub, Mul, Div,
        Neg, Not,
        Lt, Le, Eq, Ne, Ge, Gt, And, Or,
        Call1,       ///< apply MathFn1(a) to the top
        Call2,       ///< apply MathFn2(a) to the top two
        Select3,     ///< select(c, neg, nonneg)
        Select4,     ///< select(c, neg, zero, pos)
        JumpIfZero,  ///< pop; jump to `a` when zero
        Jump,        ///< jump to `a`
        Call,        ///< call callee `a` with `b` arguments from the top of the stack
        Unsupported, ///< an internal or pattern function: pops `b` arguments, pushes 0
        Internal,    ///< internal function `a` (functions.inc's numbering) of the top `b` values
        External,    ///< external function `a` (a pattern or pigment channel) of the top `b` values
        Local,       ///< push local slot `a`
        StoreLocal,  ///< pop into local slot `a`
        LoopTest,    ///< unless local `b` <= local `b + 1` (counter, limit), jump to `a`
        LoopNext     ///< add 1 to local `b`; while it stays <= local `b + 1`, jump back to `a`
    };
    Op op = Op::Const;
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    double value = 0.0;
};

/// A compiled float function of named parameters. Immutable once built; evaluate() is thread-safe.
class FunctionProgram {
public:
    /// A program over `params` (in call order); the body is appended with the emit functions.
    explicit FunctionProgram(std::vector<std::string> params);

    /// The parameter names in call order (x, y, z for `function { ... }`).
    const std::vector<std::string>& params() const { return m_params; }
    /// How many arguments evaluate() takes.
    std::size_t arity() const { return m_params.size(); }

    /// Evaluates the function; `args` must hold arity() values (missing ones read as 0, extra ones are ignored).
    /// Allocates nothing for programs of ordinary depth; never throws.
    double evaluate(std::span<const double> args, const EvalContext& context = {}) const;

    /// Why the function cannot be evaluated faithfully yet (it calls an internal or pattern function, directly
    /// or through a callee), or empty when it can. Such calls evaluate to 0.
    const std::string& unsupported() const { return m_unsupported; }

    // --- building (used by the parser's function compiler) ---
    /// Appends an instruction and returns its index; tracks the stack depth it needs.
    std::size_t emit(Instruction ins);
    /// Appends a call of `callee` with `nargs` arguments already pushed.
    void emit_call(std::shared_ptr<const FunctionProgram> callee, std::uint32_t nargs);
    /// Appends a call of `external` with `nargs` arguments already pushed.
    void emit_external(std::shared_ptr<const ExternalFunction> external, std::uint32_t nargs);
    /// Appends a call of an unsupported function (internal(n), a pattern), recording `reason`.
    void emit_unsupported(std::uint32_t nargs, const std::string& reason);
    /// Makes sure local slots 0 .. n-1 exist (loop counters and limits of sum() and prod()).
    void require_locals(std::uint32_t n) { m_locals = std::max(m_locals, n); }
    /// How many local slots evaluate() sets aside.
    std::uint32_t locals() const { return m_locals; }
    /// Index the next instruction will have (a jump target).
    std::size_t size() const { return m_code.size(); }
    /// Sets the target of the jump at `index`.
    void patch_jump(std::size_t index, std::size_t target) { m_code[index].a = static_cast<std::uint32_t>(target); }
    /// Corrects the tracked stack depth where control flow joins (after the second branch of `?:`).
    void adjust_depth(int delta) { m_depth += delta; }
    /// The instructions, for tests and debugging.
    const std::vector<Instruction>& code() const { return m_code; }
    /// The same parameters and code, calling equal callees (calls of external functions compare by count: their
    /// blocks are compared where the scene description holds them).
    bool operator==(const FunctionProgram& o) const;

private:
    double run(const double* args, std::size_t nargs, double* stack, const EvalContext& context) const;
    /// Values a run needs in its stack buffer: the local slots, then the operand stack.
    std::size_t frame_size() const { return m_locals + static_cast<std::size_t>(m_max_depth) + 1; }

    std::vector<std::string> m_params;
    std::vector<Instruction> m_code;
    std::vector<std::shared_ptr<const FunctionProgram>> m_callees;
    std::vector<std::shared_ptr<const ExternalFunction>> m_externals;
    std::string m_unsupported;
    int m_depth = 0;      ///< stack depth after the last instruction (straight-line estimate)
    int m_max_depth = 0;  ///< the deepest the stack gets
    std::uint32_t m_locals = 0;  ///< local slots, kept at the bottom of the stack buffer
};

/// A shared compiled function inside the plain-data scene description: copies share it, and two compare equal
/// when their programs do (so a scene parsed twice compares equal).
struct SharedFunction : std::shared_ptr<const FunctionProgram> {
    SharedFunction() = default;
    SharedFunction(std::shared_ptr<const FunctionProgram> p)  // NOLINT: converts like the pointer
        : std::shared_ptr<const FunctionProgram>(std::move(p)) {}
    bool operator==(const SharedFunction& o) const {
        return get() == o.get() || (get() && o.get() && *get() == *o.get());
    }
};

}  // namespace wardray::function
