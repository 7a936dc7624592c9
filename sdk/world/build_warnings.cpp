// A navmesh build's warnings about the level it was given: meshes that look wound clockwise, a
// level that looks given in other units than metres or with z up. Each is a plausible wrong answer
// the build would otherwise give in silence (issue 33); none fails the build.
#include <cmath>
#include <cstring>
#include <iomanip>
#include <mutex>
#include <map>
#include <sstream>
#include <string>

#include "level/frame_check.h"
#include "level/level_hash.h"
#include "level/winding_check.h"
#include "world/world.h"

namespace nl {
namespace {

// Two significant figures, and no exponent: "0.012", "4.3", "420".
std::string figure(float x) {
    if (std::abs(x) >= 100.0f) return std::to_string(std::lround(x));
    std::ostringstream out;
    out << std::setprecision(2) << x;
    return out.str();
}

}  // namespace

namespace {

// The estimate in `known` under `key`, or `measure()`'s, kept there for the next build (`known`
// emptied first when it holds `most`).
template <typename Key, typename Estimate, typename Measure>
Estimate remembered(std::mutex& mutex, std::map<Key, Estimate>& known, size_t most, const Key& key, Measure&& measure) {
    {
        std::lock_guard lock(mutex);
        if (const auto found = known.find(key); found != known.end()) return found->second;
    }
    const Estimate measured = measure();  // outside the lock: builds on other threads go on
    std::lock_guard lock(mutex);
    if (known.size() >= most) known.clear();
    known.emplace(key, measured);
    return measured;
}

// A key for triangles [first, end) of `level`, as winding_estimates_ keeps them: their corners'
// bits a word at a time (the level hash goes a byte at a time, for files; this one is never stored).
uint64_t corners_key(const BuildTriangles& level, size_t first, size_t end) {
    uint64_t h = 14695981039346656037ull;
    for (size_t i = first; i < end; ++i)
        for (uint32_t corner : level.mesh.triangles[i])
            for (int axis = 0; axis < 3; ++axis) {
                uint32_t bits;
                std::memcpy(&bits, &level.mesh.vertices[corner][axis], 4);
                h = (h ^ bits) * 1099511628211ull;
            }
    return h;
}

}  // namespace

void World::warn_of_level(const BuildTriangles& triangles, uint64_t hash, const AgentType& agent,
                          NavMeshProvenance& made_for) {
    made_for.turned_over_meshes = warn_turned_over(triangles, agent);
    made_for.warnings =
        warn_of_frame(triangles, hash, agent) | (made_for.turned_over_meshes.empty() ? 0u : uint32_t(kWarnedClockwise));
}

std::vector<Handle> World::warn_turned_over(const BuildTriangles& triangles, const AgentType& agent) {
    std::vector<Handle> turned;
    std::string said;
    float as_given = 0.0f, turned_over = 0.0f;
    const auto& starts = triangles.mesh_starts;
    for (size_t k = 0; k < starts.size(); ++k) {
        const size_t end = triangles.mesh_end(k);
        // An obstacle is never walked on, whichever way it faces.
        if (end == starts[k].first || triangles.areas[starts[k].first] == kObstacleArea) continue;
        const auto key = std::make_tuple(starts[k].mesh.packed(), corners_key(triangles, starts[k].first, end),
                                         agent.max_slope, agent.height);
        const WindingEstimate e = remembered(estimates_mutex_, winding_estimates_, kMaxEstimates, key, [&] {
            return estimate_winding(triangles.mesh, starts[k].first, end - starts[k].first, agent.max_slope,
                                    agent.height);
        });
        if (!looks_turned_over(e)) continue;
        turned.push_back(starts[k].mesh);
        as_given += e.floor_as_given;
        turned_over += e.floor_turned_over;
        if (turned.size() <= 8)
            said += concat(turned.size() > 1 ? ", " : "", "{", starts[k].mesh.index1 & kHandleSlotMask, ", ",
                           starts[k].mesh.revision, "}");
    }
    const bool one = turned.size() == 1;
    if (!turned.empty())
        logger_.log(LogLevel::Warning,
                    concat("the navmesh was built on ", turned.size(), one ? " mesh that looks" : " meshes that look",
                           " wound clockwise (nl_mesh_id ", said, turned.size() > 8 ? ", ..." : "", "): turned over, ",
                           one ? "it" : "they", " would hold ", std::lround(turned_over),
                           " m2 of floor for this agent, as given ", std::lround(as_given),
                           " m2. A triangle's front is the side its corners run counter-clockwise from; "
                           "register meshes wound clockwise (Godot's) with NL_MESH_CLOCKWISE"));
    return turned;
}

uint32_t World::warn_of_frame(const BuildTriangles& triangles, uint64_t hash, const AgentType& agent) {
    // Only meshes that did not say their units are measured for them, and only those that did not
    // say their up axis for it: what the estimate reads is the level (its hash) and, per mesh, those two.
    const auto& starts = triangles.mesh_starts;
    std::vector<MeshFrame> frames(starts.size());
    Fnv1a64 said;
    for (size_t k = 0; k < starts.size(); ++k) {
        try {
            frames[k] = level_->info(starts[k].mesh).frame;
        } catch (const Error& e) {
            if (e.code() != ErrorCode::InvalidHandle) throw;  // removed since: measured as not said
        }
        said.word(uint32_t(starts[k].first));
        said.word(uint32_t(frames[k].metres_per_unit == 0.0f) | uint32_t(frames[k].up == UpAxis::NotSaid) << 1);
    }
    const auto measure = [&] {
        std::vector<uint32_t> sized, floors;
        for (size_t k = 0; k < starts.size(); ++k)
            for (size_t t = starts[k].first; t < triangles.mesh_end(k); ++t) {
                if (frames[k].metres_per_unit == 0.0f) sized.push_back(uint32_t(t));
                if (frames[k].up == UpAxis::NotSaid && triangles.areas[t] != kObstacleArea)
                    floors.push_back(uint32_t(t));
            }
        return estimate_frame(triangles.mesh, sized, floors, agent.max_slope, agent.height);
    };
    const FrameEstimate e = remembered(estimates_mutex_, frame_estimates_, kMaxEstimates,
                                       std::make_tuple(hash, said.value(), agent.max_slope, agent.height), measure);
    logger_.log(LogLevel::Debug,
                concat("the level's frame, measured for the agent: floor with y up ", std::lround(e.floor_y_up),
                       " m2, with z up ", std::lround(e.floor_z_up), " m2; walls ", figure(e.wall_height), " m tall; ",
                       figure(e.across), " m across"));
    uint32_t warned = 0;
    if (looks_z_up(e)) {
        warned |= kWarnedZUp;
        logger_.log(
            LogLevel::Warning,
            concat("the level looks as if z were its up axis: with z up it would hold ", std::lround(e.floor_z_up),
                   " m2 of floor for this agent, with y up ", std::lround(e.floor_y_up),
                   " m2. NavLink's y is up; register meshes made with z up (Blender's, 3ds Max's own frame) with "
                   "nl_mesh_def.up_axis NL_UP_AXIS_Z, or NL_UP_AXIS_Y to say y is up"));
    }
    const std::string said_metres = "; a mesh registered with nl_mesh_def.metres_per_unit 1 says metres";
    if (looks_larger_than_metres(e, agent.height)) {
        warned |= kWarnedUnits;
        logger_.log(
            LogLevel::Warning,
            concat("the level's walls are ", figure(e.wall_height),
                   " m tall (the median by area of its triangles too steep "
                   "to walk) for an agent ",
                   figure(agent.height), " m tall, and the level is ", figure(e.across),
                   " m across: are its units metres? Register meshes in other units with nl_mesh_def.metres_per_unit "
                   "(0.01 for centimetres, 0.001 for millimetres, 0.0254 for inches)",
                   said_metres));
    } else if (looks_smaller_than_metres(e, agent.height)) {
        warned |= kWarnedUnits;
        logger_.log(
            LogLevel::Warning,
            concat("the whole level is ", figure(e.across), " m across, less than two agents are tall (",
                   figure(agent.height),
                   " m): are the level's units metres, and the agent's lengths? Register meshes in other units with "
                   "nl_mesh_def.metres_per_unit (1000 for kilometres)",
                   said_metres));
    }
    return warned;
}

}  // namespace nl
