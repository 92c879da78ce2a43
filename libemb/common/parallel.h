#pragma once
/// @file
/// A fixed split of independent work over the machine's cores.
///
/// The work is always cut into the same tasks, whatever the number of threads that run them,
/// and each task writes its own output: results do not depend on the thread count (a
/// reduction run on one core or two gives the same numbers, issue 12). Threads: the cores
/// the process may use (std::thread::hardware_concurrency), at most `EMB_NUM_THREADS` if that
/// variable is set to a positive integer.

#include <functional>

namespace emb {

/// Threads ParallelFor uses (≥ 1).
int WorkerThreads();

/// Runs fn(0) … fn(tasks − 1), each exactly once, on up to WorkerThreads() threads (the
/// calling thread included); returns when all have finished. The first exception a task
/// throws is rethrown here (after every task has ended).
void ParallelFor(int tasks, const std::function<void(int task)>& fn);

}  // namespace emb
