#include "src/core/background.hpp"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace cg {

void lower_thread_priority() {
#if defined(__linux__)
  // On Linux the nice value belongs to the thread (its kernel task id), not to the process. Raising it
  // needs no privilege; failure only costs speed, so it is not reported.
  (void)setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
}

}  // namespace cg
