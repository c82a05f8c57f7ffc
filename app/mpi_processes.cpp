// join_processes() on Open MPI: the one file that includes mpi.h; the ranks of MPI_COMM_WORLD as a Communicator.
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include "app/processes.h"

namespace wardray::app {

namespace {

/// MPI_COMM_WORLD; MPI_Init on construction, MPI_Finalize on destruction. Only the main thread calls MPI (the
/// render's worker threads never do), so MPI_THREAD_FUNNELED is all it needs.
class MpiCommunicator final : public render::Communicator {
public:
    MpiCommunicator() {
        int provided = 0;
        MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
        MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
        MPI_Comm_size(MPI_COMM_WORLD, &m_size);
    }
    ~MpiCommunicator() override { MPI_Finalize(); }
    MpiCommunicator(const MpiCommunicator&) = delete;
    MpiCommunicator& operator=(const MpiCommunicator&) = delete;

    int rank() const override { return m_rank; }
    int size() const override { return m_size; }

    [[noreturn]] void abort(int status) override {
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, status);
        std::_Exit(status);
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

    // Waits for `request` asleep between polls (20 us growing to 1 ms), not spinning as MPI's own wait does: a rank
    // that is through with its share of a wave leaves the processor to the ranks still working on theirs.
    static void wait(MPI_Request& request) {
        auto pause = std::chrono::microseconds(20);
        for (int done = 0;;) {
            MPI_Test(&request, &done, MPI_STATUS_IGNORE);
            if (done) return;
            std::this_thread::sleep_for(pause);
            pause = std::min(pause * 2, std::chrono::microseconds(1000));
        }
    }

    int m_rank = 0;
    int m_size = 1;
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
