// The build's progress, told to the host between Recast's steps, and the host's caller's cancel,
// which ends the build.
#pragma once

#include "navlink/plugin.h"

namespace nl::recast {

class BuildProgress {
public:
    explicit BuildProgress(const nl_plugin_host& host) : host_(host) {}

    // Tells the host (when its table has report_build_progress); throws BuildFailure with CANCELLED
    // when the host's caller asked to stop.
    void report(float fraction, const char* stage) const;

private:
    const nl_plugin_host& host_;
};

}  // namespace nl::recast
