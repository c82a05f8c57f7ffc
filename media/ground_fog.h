// Ground fog: the mean density of POV-Ray's fog_type 2 between two heights, in closed form.
#pragma once

namespace wardray::media {

/// The mean ground-fog density along a straight path from fog height `start` to `end`, heights measured as
/// (height along up − fog_offset) / fog_alt. The density is 1 at and below 0 and 1/(1 + h²) above, so its
/// integral over h is atan(h) above 0 (POV-Ray's ComputeGroundFogColour).
double ground_fog_density(double start, double end);

}  // namespace wardray::media
