// Gamma: POV-Ray 3.7's transfer functions (neutral, power law, sRGB) and the way it chains two of them.
#pragma once

namespace wardray {

/// A transfer function between linear light and encoded values, one of the three POV-Ray 3.7 knows.
struct GammaCurve {
    /// Which family the curve belongs to.
    enum class Kind { Neutral, PowerLaw, Srgb };
    Kind kind = Kind::Neutral;
    double gamma = 1.0;  ///< a power law's decoding exponent: linear = encoded^gamma

    /// The identity.
    static GammaCurve neutral() { return {}; }
    /// The power law with decoding exponent `decoding_gamma` (> 0); within 1 % of 1 it is the identity.
    static GammaCurve power_law(double decoding_gamma);
    /// The sRGB curve (IEC 61966-2-1), linear segment included, extended by its formula beyond 1.
    static GammaCurve srgb() { return {Kind::Srgb, 2.2}; }

    /// Linear to encoded; a power law encodes negatives as 0.
    double encode(double linear) const;
    /// Encoded to linear; a power law decodes negatives as 0.
    double decode(double encoded) const;
    bool is_neutral() const { return kind == Kind::Neutral; }
    /// The curve's rough exponent: 1, the power law's own, or 2.2 for sRGB.
    double approximate_gamma() const { return kind == Kind::Neutral ? 1.0 : gamma; }
    /// Whether chaining this curve's decoding with `other`'s encoding is (nearly) the identity.
    bool matches(const GammaCurve& other) const;
    bool operator==(const GammaCurve&) const = default;
};

/// Values encoded with one curve re-encoded with another: encode(x) = to.encode(from.decode(x)).
/// POV-Ray's output files, sRGB colour literals and antialiasing comparisons all go through one of these.
struct GammaTranscoding {
    GammaCurve from;  ///< decoded first (the scene's working gamma)
    GammaCurve to;    ///< then encoded (the file's gamma)

    /// `from`-encoded to `to`-encoded.
    double encode(double x) const { return to.encode(from.decode(x)); }
    /// `to`-encoded back to `from`-encoded.
    double decode(double x) const { return from.encode(to.decode(x)); }
    bool is_neutral() const { return from.is_neutral() && to.is_neutral(); }
    bool operator==(const GammaTranscoding&) const = default;
};

/// POV-Ray 3.7's transcoding from `working` to `target`, with its simplifications: a neutral working curve
/// leaves `target` alone, matching curves cancel, and two power laws (or one and the identity) fold into one.
/// Image inputs (image_map, not rendered yet) will take texels into the working gamma with
/// `transcoding(working, file_gamma).decode(v)`: file_gamma from `gamma G` in the image_map if given, else the
/// file's own (PNG: its sRGB or gAMA chunk, else sRGB; HDR and EXR: neutral), else sRGB; but a scene that set
/// assumed_gamma under #version < 3.7 takes untagged files to be in the working gamma, and with gamma handling off
/// (GlobalSettings::gamma_handling) texels are used as they are.
GammaTranscoding transcoding(const GammaCurve& working, const GammaCurve& target);

}  // namespace wardray
