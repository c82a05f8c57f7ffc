// The photon file: "wardray photons 1\n", the two sets' sizes and exponent offsets and the spacing, then each
// photon as 18 bytes (position as three little-endian floats, RGBE, the two direction bytes).
#include "photons/photon_file.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <istream>
#include <ostream>
#include <string>

namespace wardray::photons {

namespace {

constexpr char kMagic[] = "wardray photons 1\n";
constexpr std::size_t kPhotonBytes = 18;
// A count beyond any photon pass (POV-Ray's own maps stop far below), so a damaged size is refused before any
// allocation rather than attempted.
constexpr std::uint64_t kMaxPhotons = std::uint64_t{1} << 32;

static_assert(std::endian::native == std::endian::little, "photon files are written little-endian as in memory");

template <typename T>
void put(std::ostream& out, T value) {
    out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

template <typename T>
T get(std::istream& in) {
    T value{};
    if (!in.read(reinterpret_cast<char*>(&value), sizeof value)) throw PhotonFileError("the file is cut short");
    return value;
}

void put_set(std::ostream& out, const std::vector<Photon>& set) {
    std::string bytes(set.size() * kPhotonBytes, '\0');
    char* at = bytes.data();
    for (const Photon& p : set) {
        std::memcpy(at, p.position.data(), 12);
        std::memcpy(at + 12, p.rgbe.data(), 4);
        at[16] = static_cast<char>(p.theta);
        at[17] = static_cast<char>(p.phi);
        at += kPhotonBytes;
    }
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::vector<Photon> get_set(std::istream& in, std::uint64_t count) {
    std::vector<Photon> set;
    constexpr std::uint64_t kChunk = 1 << 16;  // read in chunks: a wrong count fails at the file's end, not in new
    std::string bytes;
    for (std::uint64_t done = 0; done < count;) {
        const std::uint64_t n = std::min(kChunk, count - done);
        bytes.resize(n * kPhotonBytes);
        if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
            throw PhotonFileError("the file is cut short");
        for (std::uint64_t i = 0; i < n; ++i) {
            const char* at = bytes.data() + i * kPhotonBytes;
            Photon p;
            std::memcpy(p.position.data(), at, 12);
            std::memcpy(p.rgbe.data(), at + 12, 4);
            p.theta = static_cast<std::int8_t>(at[16]);
            p.phi = static_cast<std::int8_t>(at[17]);
            for (float c : p.position)
                if (!std::isfinite(c)) throw PhotonFileError("a photon's position is not a finite number");
            set.push_back(p);
        }
        done += n;
    }
    return set;
}

}  // namespace

void write_photon_file(std::ostream& out, const ShotPhotons& shot) {
    out.write(kMagic, sizeof kMagic - 1);
    put<std::uint64_t>(out, shot.surface.size());
    put<std::uint64_t>(out, shot.media.size());
    put<std::int32_t>(out, shot.surface_offset);
    put<std::int32_t>(out, shot.media_offset);
    put<double>(out, shot.spacing);
    put_set(out, shot.surface);
    put_set(out, shot.media);
}

ShotPhotons read_photon_file(std::istream& in) {
    char magic[sizeof kMagic - 1] = {};
    if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0)
        throw PhotonFileError("not a wardray photon file (of this version)");
    ShotPhotons shot;
    const auto surface = get<std::uint64_t>(in);
    const auto media = get<std::uint64_t>(in);
    if (surface > kMaxPhotons || media > kMaxPhotons) throw PhotonFileError("its photon counts are damaged");
    shot.surface_offset = get<std::int32_t>(in);
    shot.media_offset = get<std::int32_t>(in);
    shot.spacing = get<double>(in);
    // Offsets are powers of two from the spacing (flux_exponent_offset): a few dozen at most.
    if (std::abs(shot.surface_offset) > 1000 || std::abs(shot.media_offset) > 1000)
        throw PhotonFileError("its exponent offsets are damaged");
    shot.surface = get_set(in, surface);
    shot.media = get_set(in, media);
    if (in.peek() != std::char_traits<char>::eof()) throw PhotonFileError("it has bytes after its photons");
    return shot;
}

}  // namespace wardray::photons
