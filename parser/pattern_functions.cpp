// Pattern and pigment functions: the pattern or pigment block with the texture layer's evaluation.
#include "parser/pattern_functions.h"

#include <array>
#include <utility>

namespace wardray::parser {

namespace {

// The point of the first three arguments (missing ones are 0).
Vec3 point_of(const double* args, std::size_t n) {
    return {n > 0 ? args[0] : 0.0, n > 1 ? args[1] : 0.0, n > 2 ? args[2] : 0.0};
}

class PatternFunction final : public ExternalFunction {
public:
    PatternFunction(std::shared_ptr<const Pigment> block, const ParseOptions& options)
        : m_block(std::move(block)), m_value(options.pattern_value) {}
    double evaluate(const double* args, std::size_t n, const EvalContext& context) const override {
        return m_value(m_block->pattern, point_of(args, n), context.noise_generator);
    }

private:
    std::shared_ptr<const Pigment> m_block;
    std::function<double(const Pattern&, const Vec3&, int)> m_value;
};

class PigmentChannel final : public ExternalFunction {
public:
    PigmentChannel(std::shared_ptr<const Pigment> block, int channel, const ParseOptions& options)
        : m_block(std::move(block)), m_channel(channel), m_value(options.pigment_value) {}
    double evaluate(const double* args, std::size_t n, const EvalContext& context) const override {
        return channel_value(m_value(*m_block, point_of(args, n), context.noise_generator), m_channel);
    }

private:
    std::shared_ptr<const Pigment> m_block;
    int m_channel;
    std::function<Color(const Pigment&, const Vec3&, int)> m_value;
};

class SplineChannel final : public ExternalFunction {
public:
    SplineChannel(std::shared_ptr<const Spline> spline, int channel) : m_spline(std::move(spline)), m_channel(channel) {}
    double evaluate(const double* args, std::size_t n, const EvalContext&) const override {
        const std::array<double, 5> v = evaluate_spline(*m_spline, m_spline->type, n > 0 ? args[0] : 0.0);
        // Components past the spline's own are 0, as a call of it in an expression gives them.
        return m_channel < m_spline->terms ? v[static_cast<std::size_t>(m_channel)] : 0.0;
    }

private:
    std::shared_ptr<const Spline> m_spline;
    int m_channel;
};

}  // namespace

std::shared_ptr<const ExternalFunction> make_spline_channel(std::shared_ptr<const Spline> spline, int channel) {
    return std::make_shared<const SplineChannel>(std::move(spline), channel);
}

std::shared_ptr<const ExternalFunction> make_pattern_function(std::shared_ptr<const Pigment> block,
                                                              const ParseOptions& options) {
    return std::make_shared<const PatternFunction>(std::move(block), options);
}

std::shared_ptr<const ExternalFunction> make_pigment_channel(std::shared_ptr<const Pigment> block, int channel,
                                                             const ParseOptions& options) {
    return std::make_shared<const PigmentChannel>(std::move(block), channel, options);
}

int pigment_channel(std::string_view w) {
    if (w == "x" || w == "u" || w == "red") return 0;
    if (w == "y" || w == "v" || w == "green") return 1;
    if (w == "z" || w == "blue") return 2;
    if (w == "t" || w == "filter") return 3;
    if (w == "transmit") return 4;
    if (w == "gray" || w == "grey") return 5;
    if (w == "hf") return 6;  // POV-Ray compat: MegaPOV's height-field item, which POV-Ray 3.7 still compiles
    return -1;
}

double channel_value(const Color& c, int channel) {
    switch (channel) {
        case 0: return c.r;
        case 1: return c.g;
        case 2: return c.b;
        case 3: return c.filter;
        case 4: return c.transmit;
        case 6: return (c.r + c.g / 255.0) * 0.996093;  // red the high byte, green the low one, as POV-Ray scales them
        default: return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
    }
}

}  // namespace wardray::parser
