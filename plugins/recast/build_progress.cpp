#include "build_progress.h"

#include "build_failure.h"
#include "host_table.h"

namespace nl::recast {

void BuildProgress::report(float fraction, const char* stage) const {
    if (!NL_RECAST_HOST_OFFERS(host_, report_build_progress)) return;
    const nl_status status = host_.report_build_progress(host_.context, fraction, stage);
    // Any other failure is the host's to explain; the build itself is unharmed, so it goes on.
    if (NL_FAILED(status) && (status & NL_STATUS_CANCELLED))
        fail(NL_STATUS_CANCELLED, "the navmesh build was cancelled (at ", stage, ")");
}

}  // namespace nl::recast
