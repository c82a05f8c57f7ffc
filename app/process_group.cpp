// ProcessGroup: agreements between ranks (all succeeded, rank 0's decision, rank 0's cache) and held messages.
#include "app/process_group.h"

#include <iostream>
#include <vector>

#include "app/app.h"
#include "app/processes.h"

namespace wardray::app {

ProcessGroup::ProcessGroup() : m_comm(join_processes()) {
    if (m_comm && m_comm->size() < 2) m_comm.reset();
    // Ranks other than 0 hold what they print until an agreement shows whether anyone needs to see it.
    if (!root()) m_cerr = std::cerr.rdbuf(m_held.rdbuf());
}

ProcessGroup::~ProcessGroup() {
    if (m_cerr) std::cerr.rdbuf(m_cerr);
}

bool ProcessGroup::agree(bool ok, const char* what) {
    if (!m_comm || m_released) return ok;
    // Each rank's verdict, and what it printed when it failed.
    render::Bytes mine(1, ok ? 1 : 0);
    if (!ok) {
        const std::string text = m_held.str();
        mine.insert(mine.end(), text.begin(), text.end());
    }
    m_held.str({});
    const std::vector<render::Bytes> all = m_comm->allgather(mine);
    std::vector<int> failed;
    for (std::size_t r = 0; r < all.size(); ++r)
        if (all[r].empty() || all[r][0] == 0) failed.push_back(static_cast<int>(r));
    if (failed.empty()) return true;
    if (root()) {
        const bool root_failed = failed.front() == 0;
        std::string names;
        for (const int r : failed) {
            names += (names.empty() ? "" : ", ") + std::to_string(r);
            // Rank 0 printed its own messages as they came; another rank's are shown when they may differ.
            if (r == 0 || root_failed) continue;
            const render::Bytes& b = all[static_cast<std::size_t>(r)];
            std::istringstream lines(std::string(b.begin() + 1, b.end()));
            for (std::string line; std::getline(lines, line);) std::cerr << "rank " << r << ": " << line << "\n";
        }
        std::cerr << "wardray: error: " << (failed.size() > 1 ? "ranks " : "rank ") << names << " of "
                  << m_comm->size() << " could not " << what << "; nothing written\n";
    }
    return false;
}

bool ProcessGroup::root_decides(bool value) {
    if (!m_comm) return value;
    const std::vector<render::Bytes> all = m_comm->allgather(render::Bytes(1, value ? 1 : 0));
    return !all.empty() && !all[0].empty() && all[0][0] != 0;
}

void ProcessGroup::share_cache(cache::IrradianceCache& irradiance_cache) {
    if (!m_comm) return;
    render::Bytes mine;
    if (root()) {
        std::ostringstream out;
        irradiance_cache.save(out);
        const std::string s = out.str();
        mine.assign(s.begin(), s.end());
    }
    const std::vector<render::Bytes> all = m_comm->allgather(mine);
    if (root()) return;
    std::istringstream in(std::string(all[0].begin(), all[0].end()));
    irradiance_cache.load(in);
}

void ProcessGroup::release() {
    if (!m_comm || m_released) return;
    // Another rank has nothing left to say: what it held was cleared by the last agreement.
    m_released = true;
    m_comm->release();
}

void ProcessGroup::fail(const std::string& what) {
    if (m_cerr) std::cerr.rdbuf(m_cerr);
    std::cerr << m_held.str() << "wardray: error: rank " << (m_comm ? m_comm->rank() : 0) << ": " << what << "\n";
    if (m_comm) m_comm->abort(kExitScene);
    std::exit(kExitScene);
}

}  // namespace wardray::app
