// IrradianceCache save/load: a versioned little-endian binary format that round-trips every bit of every record.
#include "cache/irradiance_cache.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <istream>
#include <ostream>
#include <string>

namespace wardray::cache {
namespace {

constexpr std::array<char, 8> kMagic{'W', 'R', 'D', 'Y', 'I', 'R', 'C', '\x1a'};
constexpr std::uint32_t kVersion = 1;
/// position, normal, irradiance (9 doubles), radius, 2 × 3 gradients (18 doubles), depth and pass (2 int32).
constexpr std::uint32_t kRecordBytes = 9 * 8 + 8 + 18 * 8 + 4 + 4;

/// FNV-1a over the record bytes, to tell a corrupt file from a valid one.
class Checksum {
public:
    void add(const unsigned char* bytes, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) m_hash = (m_hash ^ bytes[i]) * 0x100000001B3ull;
    }
    std::uint64_t value() const { return m_hash; }

private:
    std::uint64_t m_hash = 0xCBF29CE484222325ull;
};

/// Little-endian encoding into a byte buffer.
class Writer {
public:
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) m_bytes.push_back(static_cast<unsigned char>(v >> (8 * i)));
    }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) m_bytes.push_back(static_cast<unsigned char>(v >> (8 * i)));
    }
    void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
    void vec(const Vec3& v) {
        f64(v.x);
        f64(v.y);
        f64(v.z);
    }
    const std::basic_string<unsigned char>& bytes() const { return m_bytes; }
    void clear() { m_bytes.clear(); }

private:
    std::basic_string<unsigned char> m_bytes;
};

/// Little-endian decoding from a byte buffer of known size.
class Reader {
public:
    explicit Reader(const unsigned char* bytes) : m_p(bytes) {}
    std::uint32_t u32() {
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(*m_p++) << (8 * i);
        return v;
    }
    std::uint64_t u64() {
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(*m_p++) << (8 * i);
        return v;
    }
    double f64() { return std::bit_cast<double>(u64()); }
    Vec3 vec() {
        const double x = f64(), y = f64();
        return {x, y, f64()};
    }

private:
    const unsigned char* m_p;
};

/// Reads exactly `n` bytes or reports how far the file got.
bool read_exact(std::istream& in, unsigned char* bytes, std::size_t n) {
    in.read(reinterpret_cast<char*>(bytes), static_cast<std::streamsize>(n));
    return static_cast<std::size_t>(in.gcount()) == n;
}

/// A record is usable when every number is finite, the radius positive, the normal unit and depth/pass non-negative.
bool plausible(const IrradianceRecord& r) {
    bool ok = is_finite(r.position) && is_finite(r.normal) && is_finite(r.irradiance) && std::isfinite(r.radius) &&
              r.radius > 0.0 && std::fabs(length(r.normal) - 1.0) < 1e-6;
    ok = ok && r.depth >= 0 && r.pass >= 0 && r.pass < 65536;
    for (int c = 0; c < 3; ++c) ok = ok && is_finite(r.rotational[c]) && is_finite(r.translational[c]);
    return ok;
}

}  // namespace

void IrradianceCache::save(std::ostream& out) const {
    std::uint64_t total = 0;
    for (const RecordOctree& tree : m_octrees) total += tree.size();
    Writer header;
    header.u32(kVersion);
    header.u32(kRecordBytes);
    header.u32(static_cast<std::uint32_t>(m_octrees.size()));
    header.u64(total);
    out.write(kMagic.data(), kMagic.size());
    out.write(reinterpret_cast<const char*>(header.bytes().data()),
              static_cast<std::streamsize>(header.bytes().size()));

    Checksum sum;
    Writer w;
    for (const RecordOctree& tree : m_octrees) {
        for (const IrradianceRecord& r : tree.records()) {
            w.clear();
            w.vec(r.position);
            w.vec(r.normal);
            w.vec(r.irradiance);
            w.f64(r.radius);
            for (const Vec3& g : r.rotational) w.vec(g);
            for (const Vec3& g : r.translational) w.vec(g);
            w.u32(static_cast<std::uint32_t>(r.depth));
            w.u32(static_cast<std::uint32_t>(r.pass));
            sum.add(w.bytes().data(), w.bytes().size());
            out.write(reinterpret_cast<const char*>(w.bytes().data()), static_cast<std::streamsize>(w.bytes().size()));
        }
    }
    Writer trailer;
    trailer.u64(sum.value());
    out.write(reinterpret_cast<const char*>(trailer.bytes().data()),
              static_cast<std::streamsize>(trailer.bytes().size()));
    if (!out) throw CacheFileError("irradiance cache: write failed");
}

void IrradianceCache::load(std::istream& in) {
    if (m_in_pass) throw std::logic_error("IrradianceCache::load during a pass");
    std::array<char, 8> magic{};
    if (!in.read(magic.data(), magic.size()) || magic != kMagic) {
        throw CacheFileError("irradiance cache: not a wardray irradiance cache file");
    }
    std::array<unsigned char, 4 + 4 + 4 + 8> head{};
    if (!read_exact(in, head.data(), head.size())) throw CacheFileError("irradiance cache: truncated header");
    Reader hr(head.data());
    const std::uint32_t version = hr.u32();
    const std::uint32_t record_bytes = hr.u32();
    hr.u32();  // the writer's depth count, informative only
    const std::uint64_t count = hr.u64();
    if (version != kVersion) {
        throw CacheFileError("irradiance cache: format version " + std::to_string(version) +
                             " is not supported (this build reads version " + std::to_string(kVersion) + ")");
    }
    if (record_bytes != kRecordBytes) throw CacheFileError("irradiance cache: corrupt header (record size)");

    // Read everything into new octrees first, so a bad file leaves this cache untouched.
    std::vector<RecordOctree> trees;
    for (const RecordOctree& t : m_octrees) trees.push_back(t.empty_like());
    std::vector<std::vector<std::uint64_t>> per_pass;
    Checksum sum;
    std::array<unsigned char, kRecordBytes> buf{};
    int max_pass = -1;
    for (std::uint64_t i = 0; i < count; ++i) {
        if (!read_exact(in, buf.data(), buf.size())) {
            throw CacheFileError("irradiance cache: truncated at record " + std::to_string(i + 1) + " of " +
                                 std::to_string(count));
        }
        sum.add(buf.data(), buf.size());
        Reader r(buf.data());
        IrradianceRecord rec;
        rec.position = r.vec();
        rec.normal = r.vec();
        rec.irradiance = r.vec();
        rec.radius = r.f64();
        for (Vec3& g : rec.rotational) g = r.vec();
        for (Vec3& g : rec.translational) g = r.vec();
        rec.depth = static_cast<std::int32_t>(r.u32());
        rec.pass = static_cast<std::int32_t>(r.u32());
        if (!plausible(rec)) {
            throw CacheFileError("irradiance cache: corrupt record " + std::to_string(i + 1) + " of " +
                                 std::to_string(count));
        }
        if (rec.depth >= static_cast<int>(trees.size())) continue;
        trees[static_cast<std::size_t>(rec.depth)].insert(rec);
        const auto pass = static_cast<std::size_t>(rec.pass);
        if (per_pass.size() <= pass) per_pass.resize(pass + 1, std::vector<std::uint64_t>(trees.size()));
        ++per_pass[pass][static_cast<std::size_t>(rec.depth)];
        max_pass = std::max(max_pass, rec.pass);
    }
    std::array<unsigned char, 8> tail{};
    if (!read_exact(in, tail.data(), tail.size())) throw CacheFileError("irradiance cache: truncated checksum");
    if (Reader(tail.data()).u64() != sum.value()) throw CacheFileError("irradiance cache: corrupt (checksum mismatch)");

    m_octrees = std::move(trees);
    m_records_per_pass = std::move(per_pass);
    m_lookups = 0;
    m_hits = 0;
    m_pass = max_pass + 1;
}

}  // namespace wardray::cache
