// join_processes() on Open MPI: the one file that includes mpi.h; the ranks of MPI_COMM_WORLD as a Communicator.
#include <mpi.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/processes.h"

namespace wardray::app {

namespace {

/// Turns off Nagle's algorithm on this process's TCP connections, which after MPI_Init are MPI's own: Open MPI 4.1
/// talks to mpirun over PMIx on a loopback TCP connection without TCP_NODELAY, and in MPI_Finalize a few small
/// messages in a row wait for the delayed acknowledgement of the one before (40 ms on Linux): MPI_Finalize takes
/// 45-50 ms instead of 2-3 ms. TCP_NODELAY changes when bytes are sent, never what.
void send_small_messages_at_once() {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/proc/self/fd", ec)) {
        int fd = -1;
        try {
            fd = std::stoi(entry.path().filename().string());
        } catch (const std::exception&) {
            continue;
        }
        sockaddr_storage address{};
        socklen_t length = sizeof address;
        int type = 0;
        socklen_t type_length = sizeof type;
        if (fd <= 2 || getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0 ||
            (address.ss_family != AF_INET && address.ss_family != AF_INET6) ||
            getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &type_length) != 0 || type != SOCK_STREAM)
            continue;
        const int on = 1;
        setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
    }
}

/// Counters in a one-sided MPI window on rank 0, drawn from with MPI_Fetch_and_op in one passive-target epoch
/// that lasts as long as the counters. Worker threads draw while the main thread waits for them, and the calls go
/// one at a time through a mutex, so MPI_THREAD_SERIALIZED is enough.
class MpiCounters final : public render::SharedCounters {
public:
    MpiCounters(std::size_t count, int rank) : m_count(count) {
        const MPI_Aint bytes = rank == 0 ? static_cast<MPI_Aint>(count * sizeof(std::uint64_t)) : 0;
        std::uint64_t* base = nullptr;
        MPI_Win_allocate(bytes, sizeof(std::uint64_t), MPI_INFO_NULL, MPI_COMM_WORLD, &base, &m_window);
        if (rank == 0) {
            // The window's memory starts undefined: rank 0 zeroes it in an epoch of its own before anyone draws.
            MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, m_window);
            for (std::size_t i = 0; i < count; ++i) base[i] = 0;
            MPI_Win_unlock(0, m_window);
        }
        MPI_Barrier(MPI_COMM_WORLD);
        MPI_Win_lock_all(0, m_window);
    }
    ~MpiCounters() override {
        // Freeing the window waits for every rank; a rank leaving by an exception is about to abort the group
        // instead, and must not wait for ranks that will never come.
        if (std::uncaught_exceptions() > 0) return;
        MPI_Win_unlock_all(m_window);
        MPI_Win_free(&m_window);
    }
    MpiCounters(const MpiCounters&) = delete;
    MpiCounters& operator=(const MpiCounters&) = delete;

    std::uint64_t take(std::size_t index) override {
        if (index >= m_count) throw std::out_of_range("shared counters: no counter " + std::to_string(index));
        const std::uint64_t one = 1;
        std::uint64_t before = 0;
        std::lock_guard<std::mutex> lock(m_mutex);
        MPI_Fetch_and_op(&one, &before, MPI_UINT64_T, 0, static_cast<MPI_Aint>(index), MPI_SUM, m_window);
        MPI_Win_flush(0, m_window);
        return before;
    }
    std::size_t size() const override { return m_count; }

private:
    std::size_t m_count;
    MPI_Win m_window = MPI_WIN_NULL;
    std::mutex m_mutex;
};

/// MPI_COMM_WORLD, initialised on construction and finalised after release() or on destruction. MPI's life runs in
/// a thread of its own, so that MPI_Finalize (about 45 ms with Open MPI 4.1, most of it waiting for mpirun) overlaps
/// what the process does after its last exchange; MPI wants it finalised by the thread that initialised it. The
/// main thread makes the collective calls; worker threads draw from shared counters one at a time
/// (MPI_THREAD_SERIALIZED); the life thread makes none in between.
class MpiCommunicator final : public render::Communicator {
public:
    MpiCommunicator() {
        prefer_shared_memory_on_one_node();
        m_life = std::thread([this] { live(); });
        // MPI_Init sets environment variables, which a getenv elsewhere would race with: nothing runs until it is done.
        std::unique_lock<std::mutex> lock(m_life_mutex);
        m_life_changed.wait(lock, [this] { return m_initialised; });
    }
    ~MpiCommunicator() override {
        release();
        m_life.join();
    }
    MpiCommunicator(const MpiCommunicator&) = delete;
    MpiCommunicator& operator=(const MpiCommunicator&) = delete;

    int rank() const override { return m_rank; }
    int size() const override { return m_size; }

    std::unique_ptr<render::SharedCounters> shared_counters(std::size_t count) override {
        // The thread level is the same on every rank (one executable, one MPI library), so every rank takes the
        // same branch and the collective either happens everywhere or nowhere.
        if (m_thread_level < MPI_THREAD_SERIALIZED || count == 0) return nullptr;
        return std::make_unique<MpiCounters>(count, m_rank);
    }

    [[noreturn]] void abort(int status) override {
        std::fflush(stderr);
        if (!released()) MPI_Abort(MPI_COMM_WORLD, status);
        std::_Exit(status);
    }

    void release() override {
        {
            std::lock_guard<std::mutex> lock(m_life_mutex);
            m_released = true;
        }
        m_life_changed.notify_all();
    }

protected:
    std::vector<render::Bytes> do_allgather(const render::Bytes& mine) override { return exchange(mine, true); }
    std::vector<render::Bytes> do_gather(const render::Bytes& mine) override { return exchange(mine, false); }

private:
    // The sizes first, then the bytes (MPI counts are ints: a contribution over 2 GiB is refused).
    std::vector<render::Bytes> exchange(const render::Bytes& mine, bool everyone) {
        if (mine.size() > static_cast<std::size_t>(1 << 30) * 2 - 1) {
            std::fprintf(stderr, "wardray: error: rank %d: a message of %zu bytes is too large for MPI\n", m_rank,
                         mine.size());
            abort(1);
        }
        const int count = static_cast<int>(mine.size());
        std::vector<int> counts(static_cast<std::size_t>(m_size), 0);
        MPI_Request request;
        if (everyone)
            MPI_Iallgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD, &request);
        else
            MPI_Igather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
        wait(request);
        std::vector<int> offsets(counts.size(), 0);
        long long total = 0;
        for (std::size_t r = 0; r < counts.size(); ++r) {
            if (total > (1LL << 31) - 1 - counts[r]) {
                std::fprintf(stderr, "wardray: error: rank %d: an exchange over 2 GiB is too large for MPI\n", m_rank);
                abort(1);
            }
            offsets[r] = static_cast<int>(total);
            total += counts[r];
        }
        const bool receives = everyone || m_rank == 0;
        render::Bytes all(receives ? static_cast<std::size_t>(total) : 0);
        if (everyone)
            MPI_Iallgatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE,
                            MPI_COMM_WORLD, &request);
        else
            MPI_Igatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0,
                         MPI_COMM_WORLD, &request);
        wait(request);
        std::vector<render::Bytes> out;
        if (!receives) return out;
        for (std::size_t r = 0; r < counts.size(); ++r)
            out.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
        return out;
    }

    // Waits for `request` asleep between polls (10 us growing to 50 us), not spinning as MPI's own wait does: a rank
    // that is through with its share of a wave leaves the processor to the ranks still working on theirs.
    static void wait(MPI_Request& request) {
        auto pause = std::chrono::microseconds(10);
        for (int done = 0;;) {
            MPI_Test(&request, &done, MPI_STATUS_IGNORE);
            if (done) return;
            std::this_thread::sleep_for(pause);
            pause = std::min(pause * 2, std::chrono::microseconds(50));
        }
    }

    // When every rank runs on this one machine and nobody chose a point-to-point layer (`--mca pml X` reaches the
    // ranks as OMPI_MCA_pml), Open MPI's ob1 over shared memory: its default on Debian, UCX, takes 0.29 s in
    // MPI_Init on these machines against 0.12 s for ob1 (docs/mpi.md), and brings nothing within one node.
    // Across machines the default stays, for the fabrics UCX is there for.
    static void prefer_shared_memory_on_one_node() {
        const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
        const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
        if (!size || !local || std::string(size) != local || std::getenv("OMPI_MCA_pml")) return;
        setenv("OMPI_MCA_pml", "ob1", 0);
    }

    // The life thread: MPI_Init, then MPI_Finalize once the process has released the group.
    void live() {
        MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &m_thread_level);
        MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
        MPI_Comm_size(MPI_COMM_WORLD, &m_size);
        send_small_messages_at_once();
        std::unique_lock<std::mutex> lock(m_life_mutex);
        m_initialised = true;
        m_life_changed.notify_all();
        m_life_changed.wait(lock, [this] { return m_released; });
        lock.unlock();
        MPI_Finalize();
    }

    bool released() {
        std::lock_guard<std::mutex> lock(m_life_mutex);
        return m_released;
    }

    int m_rank = 0;
    int m_size = 1;
    int m_thread_level = MPI_THREAD_SINGLE;
    std::thread m_life;
    std::mutex m_life_mutex;
    std::condition_variable m_life_changed;
    bool m_initialised = false;
    bool m_released = false;
};

// Started by mpirun (Open MPI, or any launcher speaking PMIx or PMI), rather than by hand.
bool started_by_mpirun() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(name)) return true;
    return false;
}

}  // namespace

std::unique_ptr<render::Communicator> join_processes() {
    // A plain run makes no MPI call, so it starts as fast as a build without MPI.
    if (!started_by_mpirun()) return nullptr;
    return std::make_unique<MpiCommunicator>();
}

}  // namespace wardray::app
