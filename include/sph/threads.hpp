// The CPU threads sph's passes run on (OpenMP). The results of a step depend on the count, not
// on the timing: the same scene on the same count gives the same bytes.
#pragma once

namespace sph {

// The threads the calling thread's passes use.
int threadCount();
// n ≤ 0: every hardware thread.
void setThreadCount(int n);
// Makes the calling thread's passes run on it alone: for a thread beside the one that steps (a
// frame writer), whose own team would make the threads outnumber the cores.
void runSeriallyOnThisThread();

}  // namespace sph
