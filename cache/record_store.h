// RecordStore: an octree's records in insertion order, each kept once as its two parts.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cache/chunked_array.h"
#include "cache/irradiance_record.h"

namespace wardray::cache {

/// Records in insertion order, split into the part the validity test reads (RecordGeometry, one cache line, what a
/// lookup's scan fetches) and the rest (RecordValues, read only for the records a lookup uses), each in chunks so
/// that growing never copies them all. Every field is kept once: a record read whole is assembled from the two.
class RecordStore {
public:
    std::size_t size() const { return m_geometry.size(); }
    bool empty() const { return m_geometry.empty(); }
    /// Record `i`, assembled (a value, not a reference into the store).
    IrradianceRecord operator[](std::size_t i) const { return record_of(m_geometry[i], m_values[i]); }
    const RecordGeometry& geometry(std::size_t i) const { return m_geometry[i]; }
    const RecordValues& values(std::size_t i) const { return m_values[i]; }

    void push_back(const IrradianceRecord& record) {
        m_geometry.push_back(geometry_of(record));
        m_values.push_back(values_of(record));
    }
    /// Record `i`'s radius becomes `radius`.
    void set_radius(std::size_t i, double radius) { m_geometry[i].radius = radius; }
    /// What the two parts have allocated.
    std::size_t memory_bytes() const { return m_geometry.memory_bytes() + m_values.memory_bytes(); }

    /// Read-only iteration in insertion order, by value.
    using const_iterator = IndexIterator<RecordStore>;
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size()}; }

private:
    ChunkedArray<RecordGeometry> m_geometry;
    ChunkedArray<RecordValues> m_values;
};

}  // namespace wardray::cache
