// join_processes() of a build without Open MPI: every run is one process.
#include "app/processes.h"

namespace wardray::app {

std::unique_ptr<render::Communicator> join_processes() { return nullptr; }

}  // namespace wardray::app
