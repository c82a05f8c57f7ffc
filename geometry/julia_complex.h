// The complex functions of hypercomplex julia_fractals, with POV-Ray 3.7's branch choices and special cases.
#pragma once

#include "scene/shapes.h"

namespace wardray::geometry {

/// A complex number re + im i.
struct Complex {
    double re = 0.0, im = 0.0;
};

/// f(z) for the function keyword `f` of a julia_fractal (not Sqr, Cube or Reciprocal, which are no complex
/// functions here); `exponent` is pwr's. Where POV-Ray leaves its result unset (a pole), the result is 0.
Complex julia_complex_function(scene::JuliaFractal::Function f, const Complex& z, const Complex& exponent);

}  // namespace wardray::geometry
