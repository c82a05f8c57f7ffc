// RunPool: contiguous runs of small trivially copyable items carved from large chunks, reused by length.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

namespace wardray::cache {

/// Runs of T (each contiguous, its address stable until released) for many small growing lists: carved from chunks
/// of kChunk items, so that a run costs no allocator header or rounding, and a released run is kept on a free list
/// of its length for the next run of that length, or split for a shorter one. Lengths must be 1 to 8 or a multiple of
/// a quarter of their power of two (10, 12, 14, 16, 20, ...: a list grows by taking a longer run and releasing its
/// old one), which keeps the free lists few and busy: the class of a length is itself up to 8, then its power of two
/// and which quarter of it. Runs longer than a chunk are allocated on their own. Not thread-safe for writing.
template <typename T, std::size_t kChunk = 4096>
class RunPool {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) >= sizeof(T*), "a free run holds a pointer");

public:
    RunPool() = default;
    RunPool(RunPool&&) noexcept = default;
    RunPool& operator=(RunPool&&) noexcept = default;

    /// A run of n ≥ 1 items (uninitialised).
    T* allocate(std::uint32_t n) {
        if (n > kChunk) {
            m_large.emplace_back(new T[n]);
            m_large_items += n;
            return m_large.back().get();
        }
        const std::size_t wanted = length_class(n);
        if (m_free[wanted]) return pop(wanted);
        // A longer free run, split into this one and a rest of a length the lists hold (most released runs are
        // ones their nodes outgrew, which no new node asks for).
        for (std::size_t c = wanted + 1; c < m_free.size(); ++c) {
            if (!m_free[c]) continue;
            const std::uint32_t rest = class_length(c) - n;
            if (!is_length(rest)) continue;
            T* run = pop(c);
            release(run + n, rest);
            return run;
        }
        if (m_chunks.empty() || m_used + n > kChunk) {
            m_chunks.emplace_back(new T[kChunk]);
            m_used = 0;
        }
        T* run = m_chunks.back().get() + m_used;
        m_used += n;
        return run;
    }
    /// Gives back a run of n items from allocate(n).
    void release(T* run, std::uint32_t n) {
        if (n > kChunk) {
            for (auto& large : m_large) {
                if (large.get() != run) continue;
                large = std::move(m_large.back());
                m_large.pop_back();
                m_large_items -= n;
                return;
            }
            return;
        }
        T*& head = m_free[length_class(n)];
        std::memcpy(static_cast<void*>(run), static_cast<const void*>(&head), sizeof(T*));
        head = run;
    }
    /// The bytes allocated, used or not.
    std::size_t memory_bytes() const {
        return (m_chunks.size() * kChunk + m_large_items) * sizeof(T) +
               (m_chunks.capacity() + m_large.capacity()) * sizeof(std::unique_ptr<T[]>);
    }

private:
    static std::size_t length_class(std::uint32_t n) {
        if (n <= 8) return n;
        const int e = 31 - __builtin_clz(n);
        return 8 + 4 * static_cast<std::size_t>(e - 3) + ((n >> (e - 2)) & 3u);
    }
    /// The length of class c: length_class() inverted.
    static std::uint32_t class_length(std::size_t c) {
        if (c <= 8) return static_cast<std::uint32_t>(c);
        const std::size_t e = (c - 8) / 4 + 3, quarter = (c - 8) % 4;
        return static_cast<std::uint32_t>((std::size_t{4} + quarter) << (e - 2));
    }
    /// Whether n is a length of the sequence: up to 8, or a multiple of a quarter of its power of two.
    static bool is_length(std::uint32_t n) {
        if (n == 0) return false;
        if (n <= 8) return true;
        const int e = 31 - __builtin_clz(n);
        return (n & ((std::uint32_t{1} << (e - 2)) - 1)) == 0;
    }
    /// The first free run of class c, taken off its list.
    T* pop(std::size_t c) {
        T* run = m_free[c];
        std::memcpy(static_cast<void*>(&m_free[c]), static_cast<const void*>(run), sizeof(T*));
        return run;
    }

    std::vector<std::unique_ptr<T[]>> m_chunks;
    std::size_t m_used = 0;  ///< items carved from the last chunk
    std::vector<std::unique_ptr<T[]>> m_large;
    std::size_t m_large_items = 0;
    std::array<T*, 8 + 4 * 29 + 4> m_free{};
};

}  // namespace wardray::cache
