// The CPU time the whole process has used (every thread, user and system), as /bin/time sums it.
// The render service times its set-up with it and the bench its renders: on a shared machine
// another job's load moves wall-clock time far more than this.
#pragma once

namespace renderer {

// CPU seconds used so far by the whole process.
double process_cpu_seconds();

}  // namespace renderer
