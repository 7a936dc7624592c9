#include "host_log_context.h"

#include "host_table.h"

namespace nl::recast {

void host_log(const nl_plugin_host& host, nl_log_level level, const char* message) noexcept {
    if (NL_RECAST_HOST_OFFERS(host, log)) host.log(host.context, level, message);
}

void host_set_error(const nl_plugin_host& host, const char* message) noexcept {
    if (NL_RECAST_HOST_OFFERS(host, set_error)) host.set_error(host.context, message);
}

nl_status host_record_build_settings(const nl_plugin_host& host, const std::string& settings_json) noexcept {
    if (!NL_RECAST_HOST_OFFERS(host, record_build_settings)) return NL_STATUS_SUCCESS;
    return host.record_build_settings(host.context, settings_json.c_str(), settings_json.size());
}

HostLogContext::HostLogContext(const nl_plugin_host& host, Forwarding forwarding)
    : rcContext(true), host_(host), forwarding_(forwarding) {
    enableTimer(false);  // Recast's timers are RecastDemo's profiling; nothing here reads them
}

void HostLogContext::doLog(rcLogCategory category, const char* message, int length) {
    if (category == RC_LOG_PROGRESS) return;
    try {
        std::string text(message, length > 0 ? static_cast<size_t>(length) : 0);
        if (category == RC_LOG_ERROR) last_error_ = text;
        std::string line = "recast: " + text;
        const nl_log_level level = category == RC_LOG_ERROR ? NL_LOG_ERROR : NL_LOG_WARNING;
        if (forwarding_ == Forwarding::Kept) {
            kept_.emplace_back(level, std::move(line));
        } else {
            host_log(host_, level, line.c_str());
        }
    } catch (...) {
        // Out of memory while logging: drop the message, Recast's own return value still reports it.
    }
}

void HostLogContext::forward_kept() noexcept {
    for (const auto& [level, line] : kept_) host_log(host_, level, line.c_str());
    kept_.clear();
}

}  // namespace nl::recast
