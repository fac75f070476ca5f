#include "physics/executor.hpp"

#include <thread>

namespace imasim::physics {

Executor::Executor(int threads) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads_ = threads;
  if (threads_ > 1) team_ = std::make_unique<WorkerTeam>(static_cast<unsigned>(threads_));
}

}  // namespace imasim::physics
