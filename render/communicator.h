// Communicator: the processes a render is shared among (MPI ranks in app/), as two collective byte exchanges.
#pragma once

#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace wardray::render {

/// Bytes one process contributes to an exchange.
using Bytes = std::vector<unsigned char>;

/// Counters held by process 0 that every process of a group draws numbers from while it works, so that work is
/// handed out as processes become free instead of in shares fixed in advance.
class SharedCounters {
public:
    /// Ending the counters is collective: every process destroys them at the same point of its work.
    virtual ~SharedCounters() = default;
    /// Counter `index`'s value before this call added 1 to it: over the whole group each value is drawn exactly
    /// once. Safe to call from any thread of this process.
    virtual std::uint64_t take(std::size_t index) = 0;
    virtual std::size_t size() const = 0;
};

/// The group of processes that render one image together. Every process calls each collective in the same order;
/// a process that cannot go on ends the whole group (abort()), so a collective never waits forever.
class Communicator {
public:
    virtual ~Communicator() = default;

    /// This process's place in the group, 0 to size() - 1; process 0 writes every output.
    virtual int rank() const = 0;
    virtual int size() const = 0;

    /// Every process contributes `mine` and receives every contribution, in rank order (collective).
    std::vector<Bytes> allgather(const Bytes& mine);
    /// As allgather(), but only process 0 receives (others get an empty list).
    std::vector<Bytes> gather(const Bytes& mine);
    /// `count` counters, each starting at 0, shared by the group (collective). Null when this group cannot draw
    /// from shared counters; the caller then shares the work out in advance.
    virtual std::unique_ptr<SharedCounters> shared_counters(std::size_t count) {
        static_cast<void>(count);
        return nullptr;
    }
    /// Ends every process of the group with `status`, from any one of them.
    [[noreturn]] virtual void abort(int status) = 0;
    /// Declares that this process makes no more collective calls, so that leaving the group (which takes tens of
    /// milliseconds with MPI) may proceed while it finishes its own work, such as writing the image. Afterwards only
    /// destruction is allowed.
    virtual void release() {}

    /// What this process has sent and received through the collectives, and how long it spent in them
    /// (transfer and waiting for the slowest process), for --stats and the scaling model.
    struct Traffic {
        std::uint64_t exchanges = 0;
        std::uint64_t bytes_sent = 0;
        std::uint64_t bytes_received = 0;
        double seconds = 0.0;
    };
    const Traffic& traffic() const { return m_traffic; }

protected:
    virtual std::vector<Bytes> do_allgather(const Bytes& mine) = 0;
    virtual std::vector<Bytes> do_gather(const Bytes& mine) = 0;

private:
    void count(const Bytes& mine, const std::vector<Bytes>& received, double seconds);
    Traffic m_traffic;
};

/// Appends plain values to a byte buffer and reads them back in the same order (one binary, one machine type:
/// the processes of a run are the same executable).
class ByteWriter {
public:
    template <typename T>
    void put(const T& value) {
        const std::size_t at = m_bytes.size();
        m_bytes.resize(at + sizeof(T));
        std::memcpy(m_bytes.data() + at, &value, sizeof(T));
    }
    Bytes& bytes() { return m_bytes; }

private:
    Bytes m_bytes;
};

class ByteReader {
public:
    explicit ByteReader(const Bytes& bytes) : m_bytes(&bytes) {}
    /// The next value; a read past the end is a logic error (std::out_of_range).
    template <typename T>
    T get() {
        T value;
        take(&value, sizeof(T));
        return value;
    }
    /// The next `count` values into `out`, replacing what it held.
    template <typename T>
    void get(std::vector<T>& out, std::size_t count) {
        static_assert(std::is_trivially_copyable_v<T>);
        if (count > (m_bytes->size() - m_at) / sizeof(T)) throw std::out_of_range("tile exchange: a message ends early");
        out.resize(count);
        take(out.data(), count * sizeof(T));
    }
    bool done() const { return m_at == m_bytes->size(); }

private:
    void take(void* out, std::size_t n);
    const Bytes* m_bytes;
    std::size_t m_at = 0;
};

}  // namespace wardray::render
