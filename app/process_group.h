// ProcessGroup: what a run shared among processes agrees on, so that every rank takes the same path or all stop.
#pragma once

#include <memory>
#include <sstream>
#include <streambuf>
#include <string>

#include "cache/irradiance_cache.h"
#include "render/communicator.h"

namespace wardray::app {

/// The processes of one run (app/processes.h), or this process alone. Rank 0 speaks and writes; the others keep
/// what they would print and hand it to rank 0 only when they fail, so a message is printed once and names the
/// rank it came from. Every member function is collective when the run is shared.
class ProcessGroup {
public:
    /// Joins the processes started with this one (none for a plain run).
    ProcessGroup();
    /// This process on its own inside a shared run (a frame one rank renders alone): no communicator, and what it
    /// prints goes where the run's group sends it.
    struct Alone {};
    explicit ProcessGroup(Alone) {}
    ~ProcessGroup();
    ProcessGroup(const ProcessGroup&) = delete;
    ProcessGroup& operator=(const ProcessGroup&) = delete;

    /// The communicator to render with; null for one process.
    render::Communicator* communicator() const { return m_comm.get(); }
    bool shared() const { return m_comm != nullptr; }
    /// Rank 0, or the only process: the one that prints and writes.
    bool root() const { return !m_comm || m_comm->rank() == 0; }
    int rank() const { return m_comm ? m_comm->rank() : 0; }
    int size() const { return m_comm ? m_comm->size() : 1; }
    /// Every process's `mine` on rank 0, in rank order; empty elsewhere (collective).
    std::vector<render::Bytes> gather(const render::Bytes& mine) {
        return m_comm ? m_comm->gather(mine) : std::vector<render::Bytes>{mine};
    }

    /// True when every process succeeded at `what` ("parse the scene"); otherwise rank 0 prints each failed
    /// rank's messages (when it did not fail the same way itself) and one line naming the ranks, and every process
    /// returns false.
    bool agree(bool ok, const char* what);
    /// Rank 0's `value`, on every process (a decision that reads rank 0's files, such as +C's).
    bool root_decides(bool value);
    /// Makes every process's cache rank 0's (+RFI: only rank 0 reads the radiosity file).
    void share_cache(cache::IrradianceCache& irradiance_cache);
    /// Ends every process after `what` went wrong in this one, with a message naming the rank.
    [[noreturn]] void fail(const std::string& what);
    /// The run makes no more collective calls (its last frame is rendered): the processes leave the group while
    /// rank 0 writes the output. Later agreements are this process's own verdict; rank 0's failure to write then
    /// shows in its own message and exit status, which mpirun passes on.
    void release();

private:
    std::unique_ptr<render::Communicator> m_comm;
    bool m_released = false;
    std::ostringstream m_held;  ///< what a rank other than 0 printed to std::cerr since the last agreement
    std::streambuf* m_cerr = nullptr;
};

}  // namespace wardray::app
