// A Recast build context that forwards Recast's warnings and errors to the host's log and keeps the
// last error, so that a failed step can be reported with Recast's own reason. One per build.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Recast.h>

#include "navlink/plugin.h"

namespace nl::recast {

class HostLogContext : public rcContext {
public:
    // Kept: the lines wait for forward_kept(), for a context used on a task thread, where the host's
    // functions must not be called.
    enum class Forwarding { Immediate, Kept };
    explicit HostLogContext(const nl_plugin_host& host, Forwarding forwarding = Forwarding::Immediate);

    // Recast's last error message in this build, or "".
    const std::string& last_error() const { return last_error_; }
    // Logs the kept lines, in order, and forgets them; call it on the build's thread.
    void forward_kept() noexcept;

protected:
    void doLog(rcLogCategory category, const char* message, int length) override;

private:
    const nl_plugin_host& host_;
    Forwarding forwarding_;
    std::string last_error_;
    std::vector<std::pair<nl_log_level, std::string>> kept_;
};

// Calls host.log / host.set_error when the host's table has them; never throws.
void host_log(const nl_plugin_host& host, nl_log_level level, const char* message) noexcept;
void host_set_error(const nl_plugin_host& host, const char* message) noexcept;
// Calls host.record_build_settings when the host's table has it (an older host's has not: nothing is
// recorded); returns its status.
nl_status host_record_build_settings(const nl_plugin_host& host, const std::string& settings_json) noexcept;

}  // namespace nl::recast
