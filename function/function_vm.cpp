// The user-function stack machine: building programs and evaluating them.
#include "function/function_vm.h"

#include "core/constants.h"
#include "function/internal_functions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace wardray::function {

namespace {

// POV-Ray compat: comparisons in functions use the same tolerance as in expressions.
constexpr double k_epsilon = kPovEpsilon;  // POV-Ray's EPSILON
constexpr int k_local_stack = 64;

double math1(MathFn1 f, double a) {
    switch (f) {
        case MathFn1::Abs: return std::fabs(a);
        case MathFn1::Ceil: return std::ceil(a);
        case MathFn1::Floor: return std::floor(a);
        case MathFn1::Int: return std::trunc(a);
        case MathFn1::Sqrt: return std::sqrt(a);
        case MathFn1::Sin: return std::sin(a);
        case MathFn1::Cos: return std::cos(a);
        case MathFn1::Tan: return std::tan(a);
        case MathFn1::Asin: return std::asin(a);
        case MathFn1::Acos: return std::acos(a);
        case MathFn1::Atan: return std::atan(a);
        case MathFn1::Sinh: return std::sinh(a);
        case MathFn1::Cosh: return std::cosh(a);
        case MathFn1::Tanh: return std::tanh(a);
        case MathFn1::Asinh: return std::asinh(a);
        case MathFn1::Acosh: return std::acosh(a);
        case MathFn1::Atanh: return std::atanh(a);
        case MathFn1::Exp: return std::exp(a);
        case MathFn1::Ln: return std::log(a);
        case MathFn1::Log: return std::log10(a);
        case MathFn1::Radians: return a * std::numbers::pi / 180.0;
        case MathFn1::Degrees: return a * 180.0 / std::numbers::pi;
    }
    return 0.0;
}

double math2(MathFn2 f, double a, double b) {
    switch (f) {
        case MathFn2::Atan2: return std::atan2(a, b);
        case MathFn2::Pow: return std::pow(a, b);
        case MathFn2::Mod: return std::fmod(a, b);
        case MathFn2::Div: return std::trunc(a / b);
        case MathFn2::Min: return std::min(a, b);
        case MathFn2::Max: return std::max(a, b);
    }
    return 0.0;
}

// Net change of the stack depth an instruction causes (jumps and calls handled by the caller).
int stack_effect(const Instruction& ins) {
    using Op = Instruction::Op;
    switch (ins.op) {
        case Op::Const:
        case Op::Arg:
        case Op::Local: return 1;
        case Op::Neg:
        case Op::Not:
        case Op::Call1:
        case Op::Jump:
        case Op::LoopTest:
        case Op::LoopNext: return 0;
        case Op::Select3: return -2;
        case Op::Select4: return -3;
        case Op::Call:
        case Op::Internal:
        case Op::External:
        case Op::Unsupported: return 1 - static_cast<int>(ins.b);
        default: return -1;  // binary operators, Call2, JumpIfZero, StoreLocal
    }
}

}  // namespace

FunctionProgram::FunctionProgram(std::vector<std::string> params) : m_params(std::move(params)) {}

bool FunctionProgram::operator==(const FunctionProgram& o) const {
    if (m_params != o.m_params || m_code.size() != o.m_code.size() || m_callees.size() != o.m_callees.size() ||
        m_externals.size() != o.m_externals.size() || m_unsupported != o.m_unsupported || m_locals != o.m_locals)
        return false;
    for (std::size_t i = 0; i < m_code.size(); ++i) {
        const Instruction &a = m_code[i], &b = o.m_code[i];
        const bool same_value = a.value == b.value || (std::isnan(a.value) && std::isnan(b.value));
        if (a.op != b.op || a.a != b.a || a.b != b.b || !same_value) return false;
    }
    for (std::size_t i = 0; i < m_callees.size(); ++i)
        if (!(*m_callees[i] == *o.m_callees[i])) return false;
    return true;
}

std::size_t FunctionProgram::emit(Instruction ins) {
    m_depth += stack_effect(ins);
    // Const/Arg push before any pop, so the peak is the depth after the push.
    m_max_depth = std::max(m_max_depth, m_depth + (ins.op == Instruction::Op::Call ? 1 : 0));
    m_code.push_back(ins);
    return m_code.size() - 1;
}

void FunctionProgram::emit_call(std::shared_ptr<const FunctionProgram> callee, std::uint32_t nargs) {
    if (m_unsupported.empty()) m_unsupported = callee->unsupported();
    // The callee runs on its own stack above ours: reserve its locals and depth too.
    m_max_depth = std::max(m_max_depth, m_depth + static_cast<int>(callee->frame_size()));
    Instruction ins;
    ins.op = Instruction::Op::Call;
    ins.a = static_cast<std::uint32_t>(m_callees.size());
    ins.b = nargs;
    m_callees.push_back(std::move(callee));
    emit(ins);
}

void FunctionProgram::emit_external(std::shared_ptr<const ExternalFunction> external, std::uint32_t nargs) {
    Instruction ins;
    ins.op = Instruction::Op::External;
    ins.a = static_cast<std::uint32_t>(m_externals.size());
    ins.b = nargs;
    m_externals.push_back(std::move(external));
    emit(ins);
}

void FunctionProgram::emit_unsupported(std::uint32_t nargs, const std::string& reason) {
    if (m_unsupported.empty()) m_unsupported = reason;
    Instruction ins;
    ins.op = Instruction::Op::Unsupported;
    ins.b = nargs;
    emit(ins);
}

double FunctionProgram::evaluate(std::span<const double> args, const EvalContext& context) const {
    // Missing arguments read as 0: copy into a padded buffer only when the caller gave too few.
    std::array<double, 16> padded;
    const double* a = args.data();
    if (args.size() < m_params.size() && m_params.size() <= padded.size()) {
        std::fill(std::copy(args.begin(), args.end(), padded.begin()), padded.end(), 0.0);
        a = padded.data();
    } else if (args.size() < m_params.size()) {
        std::vector<double> big(m_params.size(), 0.0);
        std::copy(args.begin(), args.end(), big.begin());
        std::vector<double> stack(frame_size());
        return run(big.data(), big.size(), stack.data(), context);
    }
    if (frame_size() <= k_local_stack) {
        std::array<double, k_local_stack> stack;
        return run(a, m_params.size(), stack.data(), context);
    }
    std::vector<double> stack(frame_size());
    return run(a, m_params.size(), stack.data(), context);
}

double FunctionProgram::run(const double* args, std::size_t nargs, double* stack, const EvalContext& context) const {
    using Op = Instruction::Op;
    // The local slots sit below the operand stack; they start at 0 so every run is deterministic.
    double* const locals = stack;
    std::fill_n(locals, m_locals, 0.0);
    std::size_t sp = m_locals;  // index just past the top of the operand stack
    const std::size_t n = m_code.size();
    for (std::size_t pc = 0; pc < n; ++pc) {
        const Instruction& ins = m_code[pc];
        switch (ins.op) {
            case Op::Const: stack[sp++] = ins.value; break;
            case Op::Arg: stack[sp++] = ins.a < nargs ? args[ins.a] : 0.0; break;
            case Op::Add: --sp; stack[sp - 1] += stack[sp]; break;
            case Op::Sub: --sp; stack[sp - 1] -= stack[sp]; break;
            case Op::Mul: --sp; stack[sp - 1] *= stack[sp]; break;
            case Op::Div: --sp; stack[sp - 1] /= stack[sp]; break;
            case Op::Neg: stack[sp - 1] = -stack[sp - 1]; break;
            case Op::Not: stack[sp - 1] = stack[sp - 1] == 0.0 ? 1.0 : 0.0; break;
            case Op::Lt: --sp; stack[sp - 1] = stack[sp - 1] < stack[sp] ? 1.0 : 0.0; break;
            case Op::Le: --sp; stack[sp - 1] = stack[sp - 1] <= stack[sp] ? 1.0 : 0.0; break;
            case Op::Eq: --sp; stack[sp - 1] = std::fabs(stack[sp - 1] - stack[sp]) < k_epsilon ? 1.0 : 0.0; break;
            case Op::Ne: --sp; stack[sp - 1] = std::fabs(stack[sp - 1] - stack[sp]) >= k_epsilon ? 1.0 : 0.0; break;
            case Op::Ge: --sp; stack[sp - 1] = stack[sp - 1] >= stack[sp] ? 1.0 : 0.0; break;
            case Op::Gt: --sp; stack[sp - 1] = stack[sp - 1] > stack[sp] ? 1.0 : 0.0; break;
            case Op::And: --sp; stack[sp - 1] = (stack[sp - 1] != 0.0 && stack[sp] != 0.0) ? 1.0 : 0.0; break;
            case Op::Or: --sp; stack[sp - 1] = (stack[sp - 1] != 0.0 || stack[sp] != 0.0) ? 1.0 : 0.0; break;
            case Op::Call1: stack[sp - 1] = math1(static_cast<MathFn1>(ins.a), stack[sp - 1]); break;
            case Op::Call2:
                --sp;
                stack[sp - 1] = math2(static_cast<MathFn2>(ins.a), stack[sp - 1], stack[sp]);
                break;
            case Op::Select3: {
                sp -= 2;
                const double c = stack[sp - 1];
                stack[sp - 1] = c < 0.0 ? stack[sp] : stack[sp + 1];
                break;
            }
            case Op::Select4: {
                sp -= 3;
                const double c = stack[sp - 1];
                stack[sp - 1] = c < 0.0 ? stack[sp] : (c == 0.0 ? stack[sp + 1] : stack[sp + 2]);
                break;
            }
            case Op::JumpIfZero:
                --sp;
                if (stack[sp] == 0.0) pc = static_cast<std::size_t>(ins.a) - 1;
                break;
            case Op::Jump: pc = static_cast<std::size_t>(ins.a) - 1; break;
            case Op::Call: {
                // The callee's stack starts right above its arguments.
                const FunctionProgram& callee = *m_callees[ins.a];
                sp -= ins.b;
                double* callee_args = stack + sp;
                double result = 0.0;
                if (ins.b >= callee.arity()) {
                    result = callee.run(callee_args, ins.b, stack + sp + ins.b, context);
                } else {
                    result = callee.evaluate(std::span<const double>(callee_args, ins.b), context);
                }
                stack[sp++] = result;
                break;
            }
            case Op::Unsupported:
                sp -= ins.b;
                stack[sp++] = 0.0;
                break;
            case Op::Internal:
                sp -= ins.b;
                stack[sp] = internal_function(static_cast<int>(ins.a))(stack + sp, context);
                ++sp;
                break;
            case Op::External:
                sp -= ins.b;
                stack[sp] = m_externals[ins.a]->evaluate(stack + sp, ins.b, context);
                ++sp;
                break;
            case Op::Local: stack[sp++] = locals[ins.a]; break;
            case Op::StoreLocal: locals[ins.a] = stack[--sp]; break;
            case Op::LoopTest:
                // POV-Ray compat: the loop runs while counter <= limit, compared exactly; a NaN bound skips it.
                if (!(locals[ins.b] <= locals[ins.b + 1])) pc = static_cast<std::size_t>(ins.a) - 1;
                break;
            case Op::LoopNext: {
                const double next = locals[ins.b] + 1.0;
                // A counter so large that +1 leaves it unchanged would loop forever (POV-Ray hangs): stop.
                if (next != locals[ins.b] && next <= locals[ins.b + 1]) pc = static_cast<std::size_t>(ins.a) - 1;
                locals[ins.b] = next;
                break;
            }
        }
    }
    return sp > m_locals ? stack[sp - 1] : 0.0;
}

}  // namespace wardray::function
