// Quality: POV-Ray 3.7's +Q levels as the features each turns on (its QUALITY_0 .. QUALITY_9 flag sets).
#pragma once

namespace wardray::lighting {

/// What a quality level renders. POV-Ray 3.7: 0-1 each surface's pigment alone (no light), 2-3 ambient and
/// diffuse light without shadows, 4 shadows, 5 area lights in full, 6-7 refraction and transmission, 8 reflection
/// and normal perturbation, 9-11 media, fog, rainbows, radiosity and photons. Levels 0-5 also show pigments'
/// quick_color instead of the pigment.
struct QualityFeatures {
    bool lighting = true;        ///< off at 0-1 (Q_FULL_AMBIENT): a surface shows its pigment, nothing else
    bool shadows = true;         ///< Q_SHADOW, from 4
    bool area_lights = true;     ///< Q_AREA_LIGHT, from 5: below, an area light is a point light at its centre
    bool refraction = true;      ///< Q_REFRACT, from 6: light through transparent surfaces
    bool reflection = true;      ///< Q_REFLECT, from 8
    bool normals = true;         ///< Q_NORMAL, from 8: normal perturbation
    bool volume = true;          ///< Q_VOLUME, from 9: media, fog and rainbows
    bool advanced_light = true;  ///< Q_ADVANCED_LIGHT, from 9: radiosity and photons
    bool quick_colors = false;   ///< Q_QUICKC, up to 5: a pigment with a quick_color shows it
};

/// The features of +Q`level` (0..11; 10 and 11 are 9, as in POV-Ray 3.7).
inline QualityFeatures quality_features(int level) {
    QualityFeatures q;
    q.lighting = level >= 2;
    q.shadows = level >= 4;
    q.area_lights = level >= 5;
    q.refraction = level >= 6;
    q.reflection = level >= 8;
    q.normals = level >= 8;
    q.volume = level >= 9;
    q.advanced_light = level >= 9;
    q.quick_colors = level <= 5;
    return q;
}

}  // namespace wardray::lighting
