// The processes one run is shared among: the MPI ranks when started by mpirun (in a WARDRAY_MPI build), else one.
#pragma once

#include <memory>

#include "render/communicator.h"

namespace wardray::app {

/// Joins the processes started together with this one: the MPI ranks when this process was started by mpirun and
/// wardray was built with Open MPI, otherwise none (null: a plain run, with no MPI call at all). Ending the
/// communicator's life ends this process's part in the group.
std::unique_ptr<render::Communicator> join_processes();

}  // namespace wardray::app
