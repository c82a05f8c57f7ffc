// Noise for the texture layer: POV-Ray's noise lives in function/noise.h, shared with the internal functions.
#pragma once

#include "function/noise.h"

namespace wardray::texture {

using function::dnoise;
using function::dturbulence;
using function::hash3d;
using function::noise;
using function::noise_batch;
using function::pattern_rand;
using function::set_number_of_waves;
using function::turbulence;
using function::TurbulenceParams;
using function::wave_sources;
using function::WaveSource;

}  // namespace wardray::texture
