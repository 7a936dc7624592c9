#include "tile_streamer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "navmesh_contents.h"
#include "sample_error.h"

namespace nl::picture {
namespace {

constexpr float kSampleStep = 0.25f;  // metres between the points of a walk checked for a waypoint
constexpr size_t kSegmentWindow = 8;  // segments ahead of the last one an agent may have reached in a frame

float distance_to_segment(const float p[3], const float a[3], const float b[3], float& along) {
    float ab[3], ap[3], length2 = 0.0f, dot = 0.0f;
    for (int k = 0; k < 3; ++k) {
        ab[k] = b[k] - a[k];
        ap[k] = p[k] - a[k];
        length2 += ab[k] * ab[k];
        dot += ab[k] * ap[k];
    }
    along = length2 > 1e-12f ? std::clamp(dot / length2, 0.0f, 1.0f) : 0.0f;
    float d2 = 0.0f;
    for (int k = 0; k < 3; ++k) d2 += (ap[k] - along * ab[k]) * (ap[k] - along * ab[k]);
    return std::sqrt(d2);
}

}  // namespace

TileStreamer::TileStreamer(nl_world* world, nl_navmesh_id navmesh, std::string recast_json, const nl_agent_type& body)
    : world_(world), navmesh_(navmesh), recast_json_(std::move(recast_json)), body_(body) {
    nl_navmesh_info info = nl_navmesh_info_init();
    samples::check(nl_navmesh_get_info(world_, navmesh_, &info), "reading the navmesh");
    if (info.tile_width <= 0.0f) throw samples::SampleError("the navmesh is not tiled: it has no tiles to stream");
    width_ = info.tile_width;
    origin_[0] = info.tile_origin[0];
    origin_[1] = info.tile_origin[1];
    for (const nl_tile_coord& t : samples::read_tiles(world_, navmesh_)) {
        every_.push_back({t.x, t.z});
        loaded_[{t.x, t.z}] = true;
    }
}

bool TileStreamer::within(const Key& tile, const std::vector<Point>& centres, float radius) const {
    const float x0 = origin_[0] + static_cast<float>(tile.first) * width_, x1 = x0 + width_;
    const float z0 = origin_[1] + static_cast<float>(tile.second) * width_, z1 = z0 + width_;
    for (const Point& c : centres) {
        const float dx = std::max({x0 - c[0], 0.0f, c[0] - x1});
        const float dz = std::max({z0 - c[2], 0.0f, c[2] - z1});
        if (dx * dx + dz * dz <= radius * radius) return true;
    }
    return false;
}

bool TileStreamer::loaded(nl_tile_coord tile) const { return loaded_.count({tile.x, tile.z}) != 0; }

bool TileStreamer::holds(float x, float z, float margin) const {
    for (const float dx : {-margin, 0.0f, margin})
        for (const float dz : {-margin, 0.0f, margin}) {
            const Key tile{static_cast<int32_t>(std::floor((x + dx - origin_[0]) / width_)),
                           static_cast<int32_t>(std::floor((z + dz - origin_[1]) / width_))};
            if (!loaded_.count(tile)) return false;
        }
    return true;
}

void TileStreamer::remove(const Key& tile) {
    const nl_tile_coord coord{tile.first, tile.second};
    // Saved first: its polygons and the generated links it owns come back with it, as they were.
    size_t size = 0;
    std::vector<uint8_t> bytes;
    nl_status status = nl_navmesh_save_tile(world_, navmesh_, coord, nullptr, 0, &size);
    if (NL_SUCCEEDED(status)) {
        bytes.resize(size);
        status = nl_navmesh_save_tile(world_, navmesh_, coord, bytes.data(), bytes.size(), &size);
    }
    if (NL_SUCCEEDED(status)) {
        saved_[tile] = std::move(bytes);
    } else {
        saved_.erase(tile);
        std::printf("tile (%d, %d) not saved (%s): it will be built again\n", tile.first, tile.second,
                    samples::last_error_for_user().c_str());
    }
    samples::check(nl_navmesh_remove_tile(world_, navmesh_, coord), "removing a tile");
    loaded_.erase(tile);
    ++counts_.removed;
}

void TileStreamer::add(const Key& tile) {
    const auto saved = saved_.find(tile);
    if (saved != saved_.end()) {
        samples::check(nl_navmesh_add_tile_bytes(world_, navmesh_, saved->second.data(), saved->second.size()),
                       "adding a saved tile");
        ++counts_.added_from_bytes;
    } else {
        // Built again over its square (a little inside it: a box touching a neighbour builds that too).
        nl_navmesh_build_def def = nl_default_navmesh_build_def();
        def.agent_type = body_;
        if (!recast_json_.empty()) {
            def.settings_json = recast_json_.data();
            def.settings_json_length = recast_json_.size();
        }
        const float inset = 0.01f * width_;
        const float lo[3] = {origin_[0] + static_cast<float>(tile.first) * width_ + inset, 0.0f,
                             origin_[1] + static_cast<float>(tile.second) * width_ + inset};
        const float hi[3] = {lo[0] + width_ - 2.0f * inset, 0.0f, lo[2] + width_ - 2.0f * inset};
        samples::check(nl_navmesh_build_tiles(world_, navmesh_, &def, lo, hi), "building a tile");
        ++counts_.built;
    }
    loaded_[tile] = true;
}

TileStreamer::Change TileStreamer::follow(const std::vector<Point>& centres, float radius) {
    Change change;
    std::vector<Key> going, coming;
    for (const Key& tile : every_) {
        const bool wanted = within(tile, centres, radius);
        if (wanted && !loaded_.count(tile)) coming.push_back(tile);
        if (!wanted && loaded_.count(tile)) going.push_back(tile);
    }
    // Out first, so that no more are loaded at once than before or after; the navmesh keeps a tile
    // (its last one cannot go) until the others are in.
    std::vector<Key> kept;
    for (const Key& tile : going) {
        if (loaded_.size() > 1) {
            remove(tile);
            change.removed.push_back({tile.first, tile.second});
        } else {
            kept.push_back(tile);
        }
    }
    for (const Key& tile : coming) {
        add(tile);
        change.added.push_back({tile.first, tile.second});
    }
    for (const Key& tile : kept) {
        if (loaded_.size() <= 1) break;
        remove(tile);
        change.removed.push_back({tile.first, tile.second});
    }
    counts_.most_loaded = std::max(counts_.most_loaded, loaded_.size());
    return change;
}

TileStreamer::Change TileStreamer::load_all() {
    Change change;
    for (const Key& tile : every_) {
        if (loaded_.count(tile)) continue;
        add(tile);
        change.added.push_back({tile.first, tile.second});
    }
    return change;
}

std::string change_text(const TileStreamer::Change& change) {
    std::string out;
    char text[40];
    for (const nl_tile_coord& t : change.added) {
        std::snprintf(text, sizeof text, "%s+(%d, %d)", out.empty() ? "" : " ", t.x, t.z);
        out += text;
    }
    for (const nl_tile_coord& t : change.removed) {
        std::snprintf(text, sizeof text, "%s-(%d, %d)", out.empty() ? "" : " ", t.x, t.z);
        out += text;
    }
    return out;
}

void advance_on_route(StreamedRoute& route, const float position[3]) {
    if (route.points.size() < 2) return;
    const size_t last = std::min(route.points.size() - 2, route.segment + kSegmentWindow);
    float nearest = 0.0f;
    for (size_t k = route.segment, first = k; k <= last; ++k) {
        float along = 0.0f;
        const float d = distance_to_segment(position, route.points[k].position, route.points[k + 1].position, along);
        if (k == first || d < nearest) {
            nearest = d;
            route.segment = k;
            route.along = along;
        }
    }
}

std::optional<Waypoint> waypoint_on_route(const StreamedRoute& route, const TileStreamer& tiles, float margin) {
    std::optional<std::array<float, 3>> last;
    auto held = [&](const float p[3]) {
        if (!tiles.holds(p[0], p[2], margin)) return false;
        last = std::array<float, 3>{p[0], p[1], p[2]};
        return true;
    };
    bool to_the_end = !route.points.empty() && (route.points.size() > 1 || held(route.points[0].position));
    for (size_t k = route.segment; k + 1 < route.points.size() && to_the_end; ++k) {
        const nl_path_point& a = route.points[k];
        const nl_path_point& b = route.points[k + 1];
        if (a.segment != NL_SEGMENT_WALK) {
            // A link: past its take-off (the last point held before it) only when its landing is held.
            to_the_end = held(b.position);
            continue;
        }
        // From where the agent is along its segment: the tiles behind it may be gone already.
        const float from = k == route.segment ? route.along : 0.0f;
        const float length =
            std::hypot(b.position[0] - a.position[0], b.position[1] - a.position[1], b.position[2] - a.position[2]);
        const int steps = std::max(1, static_cast<int>(std::ceil(length * (1.0f - from) / kSampleStep)));
        for (int s = 0; s <= steps && to_the_end; ++s) {
            const float t = from + (1.0f - from) * static_cast<float>(s) / static_cast<float>(steps);
            const float p[3] = {a.position[0] + t * (b.position[0] - a.position[0]),
                                a.position[1] + t * (b.position[1] - a.position[1]),
                                a.position[2] + t * (b.position[2] - a.position[2])};
            to_the_end = held(p);
        }
    }
    if (to_the_end) return Waypoint{route.destination, true};
    if (!last) return std::nullopt;
    return Waypoint{*last, false};
}

}  // namespace nl::picture
