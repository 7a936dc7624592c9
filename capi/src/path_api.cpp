// nl_path_*: path requests, synchronous and queued, over the core's planner and queue.
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include "entry_guard.h"
#include "first_sizes.h"
#include "host_input.h"
#include "mapping.h"
#include "path/path_planner.h"
#include "path/path_shortfall.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::deref;
using nl::capi::guarded;
using nl::capi::read_amount;
using nl::capi::require;
using nl::capi::to_handle;
using nl::capi::to_id;

namespace {

static_assert(uint32_t(nl::PathOutcome::Failed) == NL_PATH_FAILED &&
                  uint32_t(nl::PathOutcome::Partial) == NL_PATH_PARTIAL,
              "core and header disagree on path outcomes");

nl::PathQuery read_query(const nl_path_request_def& def) {
    nl::PathQuery q;
    q.start = nl::capi::read_position(def.start, "def->start");
    q.goal = nl::capi::read_position(def.goal, "def->goal");
    q.search_half_extents = nl::capi::read_position(def.search_half_extents, "def->search_half_extents");
    if (!(q.search_half_extents.array() > 0.0f).all())
        fail(ErrorCode::InvalidArgument, "def->search_half_extents must be > 0 in each axis");
    q.capabilities = nl::capi::read_capabilities(def.capabilities, "def->");
    q.area_costs = nl::capi::read_area_costs(def.area_costs, def.area_cost_count, "def->");
    q.link_cost = read_amount(def.link_cost, "def->link_cost");
    q.max_nodes = def.max_nodes;
    q.accept_partial = def.accept_partial != 0;
    return q;
}

struct Request {
    nl_path_request_def def;
    nl::PathQuery query;
    std::shared_ptr<const nl::PathGraph> graph;
};

// Validates a request and takes the snapshot it will read: the navmesh and its links as they are now.
Request read_request(const nl::World& w, const nl_path_request_def* in) {
    require(in, "def");
    Request r;
    r.def =
        nl::capi::read_growable(*in, nl_default_path_request_def(), nl::capi::kFirstSize<nl_path_request_def>, "def");
    r.query = read_query(r.def);
    r.graph = w.navmeshes().path_graph(to_handle(r.def.navmesh));
    return r;
}

nl_path_result to_c(const nl::PathResult& r) {
    nl_path_result c{};
    c.size = sizeof(nl_path_result);
    c.outcome = static_cast<nl_path_outcome>(r.outcome);
    c.status = r.outcome == nl::PathOutcome::Failed
                   ? NL_STATUS_FAILURE | nl::capi::to_status(static_cast<ErrorCode>(r.failure))
                   : NL_STATUS_SUCCESS;
    c.point_count = static_cast<uint32_t>(r.points.size());
    c.links_used = r.links_used;
    c.nodes_visited = r.nodes_visited;
    c.out_of_nodes = r.out_of_nodes ? 1 : 0;
    c.length = r.length;
    c.cost = r.cost;
    Eigen::Map<nl::Vec3>(c.start) = r.start;
    Eigen::Map<nl::Vec3>(c.goal) = r.goal;
    return c;
}

// Writes the result, then the points with the two-call pattern (the result stays written when the
// points do not fit, so the caller learns the count and the outcome in one call).
void write_result(const nl::PathResult& r, nl_path_result* out_result, nl_path_point* out_points, uint32_t capacity,
                  uint32_t* out_count) {
    require(out_result, "out_result");
    require(out_count, "out_count");
    if (!out_points && capacity > 0) fail(ErrorCode::InvalidArgument, "out_points is null but capacity is ", capacity);
    nl::capi::write_growable(out_result, to_c(r), nl::capi::kFirstSize<nl_path_result>, "out_result");
    nl::capi::list_growable_into(r.points, out_points, capacity, out_count, nl::capi::kFirstSize<nl_path_point>,
                                 "out_points", [](const nl::PathPoint& p) { return nl::capi::to_c(p); });
}

// The status of a call that returned a result: partial paths carry PARTIAL_RESULT, as Detour's do.
nl_status with_detail(nl_status status, bool partial) {
    if (!NL_SUCCEEDED(status) || !partial) return status;
    return nl::capi::record(nullptr, nullptr, status | NL_STATUS_PARTIAL_RESULT, "");
}

// The last synchronous plan of this thread, kept so that a second call for the points (after
// asking for the count, or with too small a buffer) copies it instead of planning again. It reuses
// its memory: a synchronous search allocates nothing once warm.
struct LastPlan {
    std::weak_ptr<const nl::PathGraph> graph;  // weak: a kept plan must not keep a removed navmesh
    nl::PathQuery query;
    nl::PathResult result;
    uint64_t carrier_moves = 0;  // of the navmesh's carrier when planned: a plan from before a move is stale
    bool reusable = false;
};

uint64_t carrier_moves(const nl::PathGraph& graph) { return graph.frame() ? graph.frame()->moves() : 0; }

bool same_query(const nl::PathQuery& a, const nl::PathQuery& b) {
    return a.start == b.start && a.goal == b.goal && a.search_half_extents == b.search_half_extents &&
           a.capabilities.max_jump_distance == b.capabilities.max_jump_distance &&
           a.capabilities.max_jump_height == b.capabilities.max_jump_height &&
           a.capabilities.max_drop_height == b.capabilities.max_drop_height &&
           a.capabilities.radius == b.capabilities.radius && a.capabilities.abilities == b.capabilities.abilities &&
           a.area_costs == b.area_costs && a.link_cost == b.link_cost && a.max_nodes == b.max_nodes &&
           a.accept_partial == b.accept_partial;
}

}  // namespace

extern "C" {

NL_API nl_agent_capabilities nl_default_agent_capabilities(void) {
    const nl::AgentCapabilities core;
    return nl_agent_capabilities{core.max_jump_distance, core.max_jump_height, core.max_drop_height, core.radius,
                                 core.abilities};
}

NL_API nl_status nl_path_find(nl_world* world, const nl_path_request_def* def, nl_path_result* out_result,
                              nl_path_point* out_points, uint32_t capacity, uint32_t* out_count) {
    bool partial = false;
    const nl_status status = guarded("nl_path_find", world, [&] {
        require(out_result, "out_result");
        Request request = read_request(deref(world), def);
        thread_local LastPlan last;
        if (!(last.reusable && last.graph.lock() == request.graph && same_query(last.query, request.query) &&
              last.carrier_moves == carrier_moves(*request.graph))) {
            last.reusable = false;
            last.carrier_moves = carrier_moves(*request.graph);
            nl::plan_path(*request.graph, request.query, nullptr, last.result);
            last.graph = request.graph;
            last.query = std::move(request.query);
        }
        partial = last.result.outcome == nl::PathOutcome::Partial;
        // Kept for the next call only while the points are still owed.
        last.reusable = !out_points || capacity < last.result.points.size();
        write_result(last.result, out_result, out_points, capacity, out_count);
    });
    return with_detail(status, partial);
}

static_assert(NL_PATH_SHORTFALL_NOT_CONNECTED == uint32_t(nl::PathShortfall::NotConnected) &&
                  NL_PATH_SHORTFALL_LINK_BEYOND_BODY == uint32_t(nl::PathShortfall::LinkBeyondBody) &&
                  NL_LINK_LIMIT_ABILITIES == uint32_t(nl::LinkLimit::Abilities) &&
                  NL_LINK_LIMIT_WIDTH == uint32_t(nl::LinkLimit::Width),
              "header and core disagree on path shortfalls");

NL_API nl_status nl_path_explain(nl_world* world, const nl_path_request_def* def, nl_path_shortfall* out_shortfall) {
    return guarded("nl_path_explain", world, [&] {
        require(out_shortfall, "out_shortfall");
        const Request request = read_request(deref(world), def);
        nl::PathResult planned;
        nl::plan_path(*request.graph, request.query, nullptr, planned);
        const nl::PathShortfallReport report = nl::explain_shortfall(*request.graph, request.query, planned);
        nl_path_shortfall out{};
        out.size = sizeof out;
        out.reason = uint32_t(report.why);
        out.limit = uint32_t(report.limit);
        out.needed = report.needed;
        out.has = report.has;
        out.reversed = report.reversed ? 1u : 0u;
        out.missing_abilities = report.missing_abilities;
        out.link = to_id<nl_link_id>(report.link);
        nl::capi::copy_point(out.link_start, report.link_start);
        const std::string text = nl::describe(report, request.query);
        std::snprintf(out.text, sizeof out.text, "%s", text.c_str());
        nl::capi::write_growable(out_shortfall, out, sizeof(nl_path_shortfall), "out_shortfall");
    });
}

NL_API nl_path_request_def nl_default_path_request_def(void) {
    const nl::PathQuery core;
    nl_path_request_def def{};
    def.size = sizeof(nl_path_request_def);
    for (int i = 0; i < 3; ++i) def.search_half_extents[i] = core.search_half_extents[i];
    def.capabilities = nl_default_agent_capabilities();
    def.link_cost = core.link_cost;
    def.max_nodes = core.max_nodes;
    def.accept_partial = core.accept_partial ? 1 : 0;
    return def;
}

NL_API nl_status nl_path_request(nl_world* world, const nl_path_request_def* def, nl_path_ticket* out_ticket) {
    return guarded("nl_path_request", world, [&] {
        require(out_ticket, "out_ticket");
        nl::World& w = deref(world);
        Request request = read_request(w, def);
        nl::PathCallback callback;
        if (nl_path_callback* const c_callback = request.def.callback) {
            void* const user = request.def.user;
            callback = [c_callback, user](nl::Handle ticket, nl::PathOutcome outcome) {
                c_callback(user, to_id<nl_path_ticket>(ticket), static_cast<nl_path_outcome>(outcome));
            };
        }
        const nl::Handle ticket =
            w.paths().submit(std::move(request.graph), std::move(request.query), std::move(callback), request.def.user);
        *out_ticket = to_id<nl_path_ticket>(ticket);
    });
}

NL_API nl_status nl_path_poll(const nl_world* world, nl_path_ticket ticket, nl_path_outcome* out_outcome) {
    return guarded("nl_path_poll", world, [&] {
        require(out_outcome, "out_outcome");
        *out_outcome = static_cast<nl_path_outcome>(deref(world).paths().poll(to_handle(ticket)));
    });
}

NL_API nl_status nl_path_wait(nl_world* world, nl_path_ticket ticket, uint32_t timeout_ms,
                              nl_path_outcome* out_outcome) {
    nl::PathOutcome outcome = nl::PathOutcome::Pending;
    const nl_status status = guarded("nl_path_wait", world, [&] {
        require(out_outcome, "out_outcome");
        const std::chrono::steady_clock::duration timeout = timeout_ms == NL_PATH_WAIT_FOREVER
                                                                ? std::chrono::steady_clock::duration::max()
                                                                : std::chrono::milliseconds(timeout_ms);
        outcome = deref(world).paths().wait(to_handle(ticket), timeout);
        *out_outcome = static_cast<nl_path_outcome>(outcome);
    });
    if (NL_SUCCEEDED(status) && outcome == nl::PathOutcome::Pending)
        return nl::capi::record(nullptr, nullptr, NL_STATUS_IN_PROGRESS, "");
    return status;
}

NL_API nl_status nl_path_get_result(const nl_world* world, nl_path_ticket ticket, nl_path_result* out_result,
                                    nl_path_point* out_points, uint32_t capacity, uint32_t* out_count) {
    bool finished = false, partial = false;
    const nl_status status = guarded("nl_path_get_result", world, [&] {
        require(out_result, "out_result");
        require(out_count, "out_count");
        finished = deref(world).paths().read(to_handle(ticket), [&](const nl::PathResult& result) {
            partial = result.outcome == nl::PathOutcome::Partial;
            write_result(result, out_result, out_points, capacity, out_count);
        });
    });
    if (NL_SUCCEEDED(status) && !finished) return nl::capi::record(nullptr, nullptr, NL_STATUS_IN_PROGRESS, "");
    return with_detail(status, partial);
}

NL_API nl_status nl_path_cancel(nl_world* world, nl_path_ticket ticket) {
    return guarded("nl_path_cancel", world, [&] { deref(world).paths().cancel(to_handle(ticket)); });
}

NL_API nl_status nl_path_release(nl_world* world, nl_path_ticket ticket) {
    return guarded("nl_path_release", world, [&] { deref(world).paths().release(to_handle(ticket)); });
}

NL_API nl_path_budget nl_default_path_budget(void) {
    nl_path_budget budget{};
    budget.size = sizeof budget;
    return budget;
}

NL_API nl_status nl_path_process(nl_world* world, const nl_path_budget* budget, uint32_t* out_processed) {
    return guarded("nl_path_process", world, [&] {
        nl::World& w = deref(world);
        const nl_path_budget given = budget ? nl::capi::read_growable(*budget, nl_default_path_budget(),
                                                                      nl::capi::kFirstSize<nl_path_budget>, "budget")
                                            : nl_default_path_budget();
        if (std::isnan(given.max_milliseconds)) fail(ErrorCode::InvalidArgument, "budget->max_milliseconds is NaN");
        const uint32_t processed =
            w.paths().process(nl::ProcessBudget{given.max_requests, given.max_milliseconds, given.max_search_nodes});
        if (out_processed) *out_processed = processed;
    });
}

NL_API nl_status nl_path_take_finished(nl_world* world, nl_path_finished* out_finished, uint32_t capacity,
                                       uint32_t* out_count, uint32_t* out_remaining) {
    return guarded("nl_path_take_finished", world, [&] {
        nl::World& w = deref(world);
        require(out_count, "out_count");
        if (!out_finished && capacity > 0)
            fail(ErrorCode::InvalidArgument, "out_finished is null but capacity is ", capacity);
        // Checked before anything is taken: a refusal must lose no finished request.
        std::optional<nl::capi::ElementWriter<nl_path_finished>> writer;
        if (capacity > 0) writer.emplace(out_finished, nl::capi::kFirstSize<nl_path_finished>, "out_finished");
        thread_local std::vector<nl::FinishedRequest> taken;
        const uint32_t remaining = w.paths().take_finished(capacity, taken);
        for (size_t i = 0; i < taken.size(); ++i) {
            nl_path_finished f{};
            f.outcome = static_cast<nl_path_outcome>(taken[i].outcome);
            f.ticket = to_id<nl_path_ticket>(taken[i].ticket);
            f.user = taken[i].user;
            writer->write(i, f);
        }
        *out_count = static_cast<uint32_t>(taken.size());
        if (out_remaining) *out_remaining = remaining;
    });
}

NL_API nl_status nl_path_get_queue_stats(const nl_world* world, nl_path_queue_stats* out_stats) {
    return guarded("nl_path_get_queue_stats", world, [&] {
        require(out_stats, "out_stats");
        const nl::PathQueueStats s = deref(world).paths().stats();
        nl_path_queue_stats c{};
        c.size = sizeof(c);
        c.workers = s.workers;
        c.queued = s.queued;
        c.running = s.running;
        c.unreleased = s.unreleased;
        c.submitted = s.submitted;
        c.finished = s.finished;
        nl::capi::write_growable(out_stats, c, nl::capi::kFirstSize<nl_path_queue_stats>, "out_stats");
    });
}

}  // extern "C"

nl::AgentCapabilities nl::capi::read_capabilities(const nl_agent_capabilities& capabilities, const char* prefix) {
    nl::AgentCapabilities a;
    a.max_jump_distance = read_amount(capabilities.max_jump_distance, prefix, "capabilities.max_jump_distance");
    a.max_jump_height = read_amount(capabilities.max_jump_height, prefix, "capabilities.max_jump_height");
    a.max_drop_height = read_amount(capabilities.max_drop_height, prefix, "capabilities.max_drop_height");
    a.radius = read_amount(capabilities.radius, prefix, "capabilities.radius");
    a.abilities = capabilities.abilities;
    return a;
}

std::vector<float> nl::capi::read_area_costs(const float* costs, uint32_t count, const char* prefix) {
    constexpr uint32_t kMaxAreaCosts = 256;
    if (count > kMaxAreaCosts)
        fail(ErrorCode::InvalidArgument, prefix, "area_cost_count is ", count, " (at most ", kMaxAreaCosts, ")");
    if (count > 0 && !costs) fail(ErrorCode::InvalidArgument, prefix, "area_costs is null");
    for (uint32_t i = 0; i < count; ++i) read_amount(costs[i], prefix, "area_costs[", i, "]");
    return count > 0 ? std::vector<float>(costs, costs + count) : std::vector<float>{};
}

nl_path_point nl::capi::to_c(const nl::PathPoint& p) {
    nl_path_point c{};
    c.size = sizeof c;
    Eigen::Map<nl::Vec3>(c.position) = p.position;
    c.polygon = p.polygon;
    c.segment = p.segment;
    c.link = to_id<nl_link_id>(p.link);
    Eigen::Map<nl::Vec3>(c.apex) = p.apex;
    c.reversed = p.reversed ? 1 : 0;
    Eigen::Map<nl::Vec3>(c.carrier_position) = p.carrier_position;
    return c;
}
