#include "world_agents.h"

#include "sample_error.h"

namespace nl::samples {
namespace {

// The two-call pattern: the count first, then a buffer of that many. An agent list cannot change
// between the calls unless the host changes it, so the second call fills the whole buffer.
template <typename Item, typename Call>
std::vector<Item> read_all(Item init, Call call, const char* what) {
    uint32_t count = 0;
    check(call(nullptr, 0, &count), what);
    std::vector<Item> items(count, init);
    if (count > 0) check(call(items.data(), count, &count), what);
    items.resize(count, init);
    return items;
}

}  // namespace

nl_agent_def agent_def(const AgentProfile& profile, nl_navmesh_id navmesh, const float position[3]) {
    nl_agent_def def = nl_default_agent_def();
    def.navmesh = navmesh;
    def.height = profile.body.height;
    def.capabilities = profile.capabilities;
    for (int k = 0; k < 3; ++k) def.position[k] = position[k];
    return def;
}

std::vector<nl_agent_info> read_agents(const nl_world* world) {
    return read_all(
        nl_agent_info_init(),
        [world](nl_agent_info* out, uint32_t capacity, uint32_t* count) {
            return nl_world_get_agents(world, out, capacity, count);
        },
        "reading the agents");
}

std::vector<nl_agent_event> read_agent_events(const nl_world* world) {
    return read_all(
        nl_agent_event_init(),
        [world](nl_agent_event* out, uint32_t capacity, uint32_t* count) {
            return nl_world_get_agent_events(world, out, capacity, count);
        },
        "reading the agents' events");
}

nl_agent_info read_agent(const nl_world* world, nl_agent_id agent) {
    nl_agent_info info = nl_agent_info_init();
    check(nl_agent_get_info(world, agent, &info), "reading an agent");
    return info;
}

std::vector<nl_path_point> read_corners(const nl_world* world, nl_agent_id agent) {
    return read_all(
        nl_path_point_init(),
        [world, agent](nl_path_point* out, uint32_t capacity, uint32_t* count) {
            return nl_agent_get_corners(world, agent, out, capacity, count);
        },
        "reading an agent's corners");
}

bool in_the_air(nl_agent_state state) {
    return state == NL_AGENT_JUMPING || state == NL_AGENT_FALLING || state == NL_AGENT_TRAVERSING;
}

bool same_agent(nl_agent_id a, nl_agent_id b) { return a.index1 == b.index1 && a.revision == b.revision; }

const char* agent_state_name(nl_agent_state state) {
    switch (state) {
        case NL_AGENT_IDLE: return "idle";
        case NL_AGENT_WALKING: return "walking";
        case NL_AGENT_JUMPING: return "jumping";
        case NL_AGENT_FALLING: return "falling";
        case NL_AGENT_TRAVERSING: return "traversing";
        case NL_AGENT_WAITING: return "waiting";
        case NL_AGENT_ARRIVED: return "arrived";
        case NL_AGENT_FAILED: return "failed";
        default: return "unknown state";
    }
}

const char* agent_reason_name(nl_agent_reason reason) {
    switch (reason) {
        case NL_AGENT_REASON_NONE: return "none";
        case NL_AGENT_REASON_DESTINATION_SET: return "new destination";
        case NL_AGENT_REASON_LINK_GONE: return "link gone";
        case NL_AGENT_REASON_WORLD_CHANGED: return "links changed";
        case NL_AGENT_REASON_OFF_PATH: return "off its path";
        case NL_AGENT_REASON_NO_PATH: return "no path";
        case NL_AGENT_REASON_NAVMESH_REMOVED: return "navmesh removed";
        case NL_AGENT_REASON_CAPABILITIES_CHANGED: return "capabilities changed";
        default: return "unknown reason";
    }
}

const char* agent_event_name(nl_agent_event_kind kind) {
    switch (kind) {
        case NL_AGENT_EVENT_PATH_READY: return "path ready";
        case NL_AGENT_EVENT_LINK_STARTED: return "link started";
        case NL_AGENT_EVENT_LINK_FINISHED: return "link finished";
        case NL_AGENT_EVENT_ARRIVED: return "arrived";
        case NL_AGENT_EVENT_FAILED: return "failed";
        case NL_AGENT_EVENT_REPLANNED: return "replanned";
        default: return "unknown event";
    }
}

}  // namespace nl::samples
