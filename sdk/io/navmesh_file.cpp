#include "io/navmesh_file.h"

#include <nlohmann/json.hpp>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "io/byte_stream.h"
#include "io/file_bytes.h"
#include "io/json_input.h"
#include "io/link_json.h"
#include "level/level_hash.h"
#include "level/mesh_validation.h"
#include "navmesh/navmesh_grid.h"
#include "util/error.h"

namespace nl {
namespace {

constexpr uint8_t kMagic[8] = {0x89, 'N', 'L', 'N', 'A', 'V', 0x0D, 0x0A};
constexpr char kMade[4] = {'M', 'A', 'D', 'E'}, kGeometry[4] = {'G', 'E', 'O', 'M'}, kLinks[4] = {'L', 'I', 'N', 'K'},
               kTile[4] = {'T', 'I', 'L', 'E'};

enum LinkFlags : uint8_t { kBidirectional = 1, kGenerated = 2, kEnabled = 4 };
enum MadeFlags : uint8_t { kRidesCarrier = 1 };
enum FileFlags : uint32_t { kDeflated = 1 };

constexpr unsigned kWidestCoordinate = 6;  // bytes: 2^48 quanta hold any two coordinates within the limit
constexpr int64_t kMostUnits = int64_t(1) << 50;

// Coordinates in whole quanta of the navmesh grid (navmesh_grid.h), exact for every coordinate on it.
int64_t units(float v) { return std::llround(std::ldexp(double(v), -kNavMeshGridExponent)); }
float metres(int64_t units) { return static_cast<float>(std::ldexp(double(units), kNavMeshGridExponent)); }

// The fewest bytes (1 to 8) that hold 0..largest.
unsigned width_for(uint64_t largest) {
    unsigned w = 1;
    while (w < 8 && largest >= (uint64_t(1) << (8 * w))) ++w;
    return w;
}

// Where fixed-point coordinates start: the navmesh's lowest corner, in quanta.
struct Quantiser {
    int64_t origin[3] = {0, 0, 0};
    int64_t offset(float v, int axis) const { return units(v) - origin[axis]; }
};

Aabb bounds_of_points(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    Aabb box;
    for (const Vec3& p : a) box.grow(p);
    for (const Vec3& p : b) box.grow(p);
    return box;
}

void write_points(ByteWriter& out, const std::vector<Vec3>& points, const Quantiser& q, const unsigned widths[3]) {
    for (const Vec3& p : points)
        for (int axis = 0; axis < 3; ++axis) out.little(static_cast<uint64_t>(q.offset(p[axis], axis)), widths[axis]);
}

void write_geometry(ByteWriter& out, const NavMeshInput& in, Quantiser& q) {
    const Aabb box = bounds_of_points(in.vertices, in.detail_vertices);
    unsigned widths[3];
    for (int axis = 0; axis < 3; ++axis) {
        q.origin[axis] = units(box.min[axis]);
        widths[axis] = width_for(static_cast<uint64_t>(q.offset(box.max[axis], axis)));
    }
    out.u8(static_cast<uint8_t>(static_cast<int8_t>(kNavMeshGridExponent)));
    for (int axis = 0; axis < 3; ++axis) out.signed_varint(q.origin[axis]);
    for (unsigned w : widths) out.u8(static_cast<uint8_t>(w));
    out.varint(in.vertices.size());
    write_points(out, in.vertices, q, widths);

    const uint32_t polygons = static_cast<uint32_t>(in.polygon_sizes.size());
    out.varint(polygons);
    for (uint8_t n : in.polygon_sizes) out.u8(n);
    const unsigned corner_width = width_for(in.vertices.empty() ? 0 : in.vertices.size() - 1);
    out.u8(static_cast<uint8_t>(corner_width));
    for (uint32_t v : in.indices) out.little(v, corner_width);
    const bool areas = std::any_of(in.areas.begin(), in.areas.end(), [](uint8_t a) { return a != 0; });
    out.u8(areas ? 1 : 0);
    if (areas)
        for (uint8_t a : in.areas) out.u8(a);

    const bool detail = !in.detail_starts.empty();
    out.u8(detail ? 1 : 0);
    if (!detail) return;
    out.varint(in.detail_vertices.size());
    write_points(out, in.detail_vertices, q, widths);
    // Per polygon, its triangles' corners as offsets from the lowest it uses: a byte each for
    // Recast's detail, whose vertices are numbered polygon by polygon.
    int64_t last_base = 0;
    for (uint32_t p = 0; p < polygons; ++p) {
        const uint32_t first = in.detail_starts[p], end = in.detail_starts[p + 1];
        const auto begin_index = in.detail_indices.begin() + 3 * first, end_index = in.detail_indices.begin() + 3 * end;
        const uint32_t base = *std::min_element(begin_index, end_index),
                       top = *std::max_element(begin_index, end_index);
        const unsigned width = width_for(top - base);
        out.varint(end - first);
        out.signed_varint(int64_t(base) - last_base);
        out.u8(static_cast<uint8_t>(width));
        for (auto it = begin_index; it != end_index; ++it) out.little(*it - base, width);
        last_base = base;
    }
}

// A link point in quanta from `from` (in quanta): a link's start from the last link's (generated
// links come in order along the outline), its end and apex from its start; a few bytes each.
struct GridPoint {
    int64_t units[3];
};
GridPoint on_grid(const Vec3& p) { return GridPoint{{units(p.x()), units(p.y()), units(p.z())}}; }

void write_point(ByteWriter& out, const Vec3& p, const GridPoint& from) {
    const GridPoint at = on_grid(p);
    for (int axis = 0; axis < 3; ++axis) out.signed_varint(at.units[axis] - from.units[axis]);
}

void write_links(ByteWriter& out, const std::vector<Link>& links, const Quantiser& q) {
    out.varint(links.size());
    GridPoint last_start{{q.origin[0], q.origin[1], q.origin[2]}};
    for (size_t i = 0; i < links.size(); ++i) {
        const Link& l = links[i];
        if (l.crosses())
            fail(ErrorCode::InvalidArgument, "links[", i,
                 "] lands on another navmesh (a cross link): a navmesh file holds "
                 "one navmesh's own links");
        out.varint(static_cast<uint32_t>(l.kind));
        out.u8(static_cast<uint8_t>((l.bidirectional ? kBidirectional : 0) | (l.generated ? kGenerated : 0) |
                                    (l.enabled ? kEnabled : 0)));
        out.f32(l.cost_modifier);
        out.f32(l.arc_height);
        out.varint(l.user_data);
        out.varint(uint32_t(l.start_polygon + 1));  // kNoPolygon is 0
        out.varint(uint32_t(l.end_polygon + 1));
        write_point(out, l.start, last_start);
        last_start = on_grid(l.start);
        write_point(out, l.end, last_start);
        write_point(out, l.apex, last_start);
        const LinkRequirements& r = l.requirements;
        for (float v : {r.gap, r.length, r.rise, r.drop, r.clearance_width}) out.f32(v);
        out.varint(r.abilities);
    }
}

void write_made_for(ByteWriter& out, const AgentType& agent, const NavMeshProvenance& made_for, bool rides_carrier) {
    for (float v : {agent.radius, agent.height, agent.max_climb, agent.max_slope}) out.f32(v);
    out.u8(rides_carrier ? kRidesCarrier : 0);
    out.u64(made_for.level_hash);
    out.text(made_for.builder);
    out.text(made_for.builder_settings);
    // The link settings field by field: a tenth of their JSON.
    out.u8(made_for.links.settings.empty() ? 0 : 1);
    if (!made_for.links.settings.empty()) {
        LinkSettings settings;
        apply_settings_json(made_for.links.settings, settings);
        for (const NamedFloatSetting& f : kFloatSettings) out.f32(settings.*f.field);
        for (const NamedWholeSetting& w : kWholeSettings) out.varint(settings.*w.field);
        out.varint(settings.drop_angles.size());
        for (float angle : settings.drop_angles) out.f32(angle);
    }
    out.text(made_for.links.plugins);
    out.text(NAVLINK_CORE_VERSION);
}

void write_tile_coord(ByteWriter& out, const TileCoord& t) {
    out.signed_varint(t.x);
    out.signed_varint(t.z);
}

void write_tile(ByteWriter& out, const NavMeshInput& tile, const std::vector<Link>& links, uint64_t content_hash) {
    const TileGrid& grid = tile.tiles.grid;
    for (float v : {grid.origin_x, grid.origin_z, grid.tile_width}) out.f32(v);
    write_tile_coord(out, tile.tiles.tiles.front());
    out.u64(content_hash);
    out.f32(tile.weld_tolerance);
    out.varint(links.size());
    for (size_t i = 0; i < links.size(); ++i) {
        if (!links[i].start_tile || !links[i].end_tile)
            fail(ErrorCode::InvalidArgument, "links[", i, "] has no start or end tile: a tile's file holds the links ",
                 "placed on its navmesh");
        write_tile_coord(out, *links[i].start_tile);
        write_tile_coord(out, *links[i].end_tile);
    }
}

void write_section(ByteWriter& out, const char tag[4], ByteWriter& payload_writer) {
    for (int i = 0; i < 4; ++i) out.u8(static_cast<uint8_t>(tag[i]));
    out.u32(0);
    out.u64(payload_writer.size());
    out.append(payload_writer.bytes());
}

// The sections as written, from the deflated bytes after the header. Deflate cannot make data more
// than 1032 times smaller, so a stated size beyond that is refused before anything is allocated.
std::vector<uint8_t> inflated(const uint8_t* data, size_t size, const std::string& context) {
    ByteReader in(data, size, context);
    const uint64_t inflated_size = in.u64("the inflated size");
    if (inflated_size > 1032 * uint64_t(in.remaining()) + 64)
        fail(ErrorCode::Parse, context, ": it claims ", inflated_size, " bytes inflated, more than its ",
             in.remaining(), " deflated bytes could hold (corrupted)");
    std::vector<uint8_t> out(static_cast<size_t>(inflated_size));
    uLongf got = out.size();
    if (uncompress(out.data(), &got, in.here(), in.remaining()) != Z_OK || got != out.size())
        fail(ErrorCode::Parse, context, ": its deflated bytes do not inflate to the ", inflated_size,
             " it states (corrupted)");
    return out;
}

// --- reading ---------------------------------------------------------------------------------

void read_points(ByteReader& in, std::vector<Vec3>& points, uint32_t count, const Quantiser& q,
                 const unsigned widths[3]) {
    points.resize(count);
    for (Vec3& p : points)
        for (int axis = 0; axis < 3; ++axis)
            p[axis] = metres(q.origin[axis] + int64_t(in.little(widths[axis], "a vertex")));
}

void read_geometry(ByteReader& in, NavMeshInput& out, Quantiser& q) {
    const int exponent = static_cast<int8_t>(in.u8("the quantum"));
    if (exponent != kNavMeshGridExponent)
        fail(ErrorCode::Parse, in.context(), ": a quantum of 2^", exponent, " m (this version writes 2^",
             kNavMeshGridExponent, ")");
    for (int64_t& origin : q.origin) {
        origin = in.signed_varint("the origin");
        if (origin < -kMostUnits || origin > kMostUnits)
            fail(ErrorCode::Parse, in.context(), ": the origin is beyond the coordinate limit");
    }
    unsigned widths[3];
    for (unsigned& w : widths) {
        w = in.u8("a coordinate width");
        if (w < 1 || w > kWidestCoordinate)
            fail(ErrorCode::Parse, in.context(), ": a coordinate width of ", w, " bytes (must be 1 to ",
                 kWidestCoordinate, ")");
    }
    const uint32_t vertices = in.count("the vertex count", widths[0] + widths[1] + widths[2]);
    read_points(in, out.vertices, vertices, q, widths);

    const uint32_t polygons = in.count("the polygon count", 4);
    out.polygon_sizes.resize(polygons);
    uint64_t corners = 0;
    for (uint8_t& n : out.polygon_sizes) {
        n = in.u8("a polygon's corner count");
        corners += n;
    }
    const unsigned corner_width = in.u8("the corner width");
    if (corner_width < 1 || corner_width > 4)
        fail(ErrorCode::Parse, in.context(), ": a corner width of ", corner_width, " bytes");
    in.need(corners * corner_width, "the polygons' corners");
    out.indices.resize(corners);
    for (uint32_t& v : out.indices) v = static_cast<uint32_t>(in.little(corner_width, "a corner"));
    if (in.u8("the areas flag")) {
        in.need(polygons, "the areas");
        out.areas.resize(polygons);
        for (uint8_t& a : out.areas) a = in.u8("an area");
    }

    if (!in.u8("the detail flag")) return;
    const uint32_t detail_vertices = in.count("the detail vertex count", widths[0] + widths[1] + widths[2]);
    read_points(in, out.detail_vertices, detail_vertices, q, widths);
    out.detail_starts.reserve(size_t(polygons) + 1);
    out.detail_indices.reserve(std::min<size_t>(in.remaining(), size_t(polygons) * 3 * kMaxDetailTriangles));
    out.detail_starts.push_back(0);
    int64_t base = 0;
    for (uint32_t p = 0; p < polygons; ++p) {
        const uint32_t triangles = in.count("a polygon's detail triangle count", 3);
        if (triangles > kMaxDetailTriangles)
            fail(ErrorCode::Parse, in.context(), ": polygon ", p, " has ", triangles, " detail triangles (at most ",
                 kMaxDetailTriangles, ")");
        const int64_t step = in.signed_varint("a polygon's first detail vertex");
        if (step < -int64_t(detail_vertices) || step > int64_t(detail_vertices) || base + step < 0 ||
            base + step > int64_t(detail_vertices))
            fail(ErrorCode::Parse, in.context(), ": polygon ", p, "'s detail vertices start outside the ",
                 detail_vertices, " there are");
        base += step;
        const unsigned width = in.u8("a detail corner width");
        if (width < 1 || width > 4)
            fail(ErrorCode::Parse, in.context(), ": a detail corner width of ", width, " bytes");
        in.need(uint64_t(triangles) * 3 * width, "a polygon's detail triangles");
        for (uint32_t k = 0; k < 3 * triangles; ++k) {
            const int64_t v = base + int64_t(in.little(width, "a detail corner"));
            if (v < 0 || v >= int64_t(detail_vertices))
                fail(ErrorCode::Parse, in.context(), ": polygon ", p, "'s detail triangles use vertex ", v, " of ",
                     detail_vertices);
            out.detail_indices.push_back(static_cast<uint32_t>(v));
        }
        out.detail_starts.push_back(out.detail_starts.back() + triangles);
    }
}

Vec3 read_point(ByteReader& in, GridPoint& at, const GridPoint& from, size_t link, const char* which) {
    Vec3 p;
    for (int axis = 0; axis < 3; ++axis) {
        const int64_t offset = in.signed_varint(which);
        if (offset < -kMostUnits || offset > kMostUnits || std::llabs(from.units[axis]) > kMostUnits)
            fail(ErrorCode::Parse, in.context(), ": links[", link, "].", which, " is beyond the coordinate limit");
        at.units[axis] = from.units[axis] + offset;
        p[axis] = metres(at.units[axis]);
    }
    if (!within_coordinate_limit(p))
        fail(ErrorCode::Parse, in.context(), ": links[", link, "].", which, " is beyond the coordinate limit");
    return p;
}

void read_links(ByteReader& in, std::vector<Link>& out, const Quantiser& q) {
    const uint32_t count = in.count("the link count", 30);
    out.resize(count);
    GridPoint start{{q.origin[0], q.origin[1], q.origin[2]}}, other{};
    for (size_t i = 0; i < count; ++i) {
        Link& l = out[i];
        const uint64_t kind = in.varint("a link's kind");
        if (!(kind >= 1 && kind <= 3) && !(kind >= uint64_t(LinkKind::FirstPluginKind) && kind <= UINT32_MAX))
            fail(ErrorCode::Parse, in.context(), ": links[", i, "].kind is ", kind,
                 " (jump 1, drop 2, manual 3, or a plugin's >= 256)");
        l.kind = static_cast<LinkKind>(kind);
        const uint8_t flags = in.u8("a link's flags");
        l.bidirectional = flags & kBidirectional;
        l.generated = flags & kGenerated;
        l.enabled = flags & kEnabled;
        l.cost_modifier = in.f32("a link's cost modifier");
        l.arc_height = in.f32("a link's arc height");
        l.user_data = in.varint("a link's user data");
        l.start_polygon = static_cast<uint32_t>(in.varint("a link's start polygon") - 1);
        l.end_polygon = static_cast<uint32_t>(in.varint("a link's end polygon") - 1);
        const GridPoint last_start = start;
        l.start = read_point(in, start, last_start, i, "start");
        l.end = read_point(in, other, start, i, "end");
        l.apex = read_point(in, other, start, i, "apex");
        LinkRequirements& r = l.requirements;
        for (float* v : {&r.gap, &r.length, &r.rise, &r.drop, &r.clearance_width}) *v = in.f32("a link's requirement");
        r.abilities = in.varint("a link's abilities");
        for (float v : {l.cost_modifier, l.arc_height, r.gap, r.length, r.rise, r.drop, r.clearance_width})
            if (!(v >= 0.0f && std::isfinite(v)))
                fail(ErrorCode::Parse, in.context(), ": links[", i, "] has a cost, arc height or requirement of ", v,
                     " (must be finite and >= 0)");
    }
}

void read_made_for(ByteReader& in, NavMeshFile& out) {
    AgentType& a = out.navmesh.agent_type;
    for (float* v : {&a.radius, &a.height, &a.max_climb, &a.max_slope}) *v = in.f32("the agent type");
    const uint8_t flags = in.u8("the flags");
    out.rides_carrier = flags & kRidesCarrier;
    out.made_for.level_hash = in.u64("the level hash");
    out.made_for.builder = in.text("the builder's name");
    out.made_for.builder_settings = in.text("the builder's settings");
    if (in.u8("the link settings flag")) {
        LinkSettings settings;
        for (const NamedFloatSetting& f : kFloatSettings) settings.*f.field = in.f32("a link setting");
        for (const NamedWholeSetting& w : kWholeSettings) {
            const uint64_t v = in.varint("a link setting");
            if (v > UINT32_MAX) fail(ErrorCode::Parse, in.context(), ": the link setting ", w.name, " is ", v);
            settings.*w.field = static_cast<unsigned>(v);
        }
        settings.drop_angles.resize(in.count("the drop angle count", 4));
        for (float& angle : settings.drop_angles) angle = in.f32("a drop angle");
        try {
            validate(settings);
        } catch (const Error& e) {
            fail(ErrorCode::Parse, in.context(), ": the link settings: ", e.what());
        }
        out.made_for.links.settings = link_settings_to_json(settings);
    }
    out.made_for.links.plugins = in.text("the link-kind plugins");
    if (!out.made_for.links.plugins.empty() && !recorded_json(out.made_for.links.plugins).is_object())
        fail(ErrorCode::Parse, in.context(), ": the link-kind plugins are not a JSON object");
    out.writer = in.text("the writer's version");
}

TileCoord read_tile_coord(ByteReader& in, const char* which) {
    TileCoord t;
    for (int32_t* c : {&t.x, &t.z}) {
        const int64_t v = in.signed_varint(which);
        if (std::fabs(double(v)) > kMaxTileIndex)
            fail(ErrorCode::Parse, in.context(), ": ", which, " has an index of ", v, " (at most 2^30 either way)");
        *c = static_cast<int32_t>(v);
    }
    return t;
}

void read_tile(ByteReader& in, NavMeshFile& out) {
    TileGrid grid;
    for (float* v : {&grid.origin_x, &grid.origin_z, &grid.tile_width}) *v = in.f32("the tile grid");
    if (!std::isfinite(grid.origin_x) || !std::isfinite(grid.origin_z) || !(grid.tile_width > 0.0f) ||
        !std::isfinite(grid.tile_width) || !within_coordinate_limit(Vec3(grid.origin_x, 0.0f, grid.origin_z)))
        fail(ErrorCode::Parse, in.context(), ": a grid of tiles ", grid.tile_width, " m wide from (", grid.origin_x,
             ", ", grid.origin_z, ") (must be finite, wider than 0, within the coordinate limit)");
    out.navmesh.tiles = TileLayout{grid, {read_tile_coord(in, "the tile")}};
    out.content_hash = in.u64("the content hash");
    out.navmesh.weld_tolerance = in.f32("the weld tolerance");
    if (!(out.navmesh.weld_tolerance >= 0.0f && out.navmesh.weld_tolerance <= 1.0f))
        fail(ErrorCode::Parse, in.context(), ": a weld tolerance of ", out.navmesh.weld_tolerance, " m (0..1)");
    const uint64_t count = in.varint("the link count");
    if (count != out.links.size())
        fail(ErrorCode::Parse, in.context(), ": tiles for ", count, " links, the LINK section has ", out.links.size());
    const TileCoord at = out.navmesh.tiles.tiles.front();
    for (size_t i = 0; i < out.links.size(); ++i) {
        Link& l = out.links[i];
        l.start_tile = read_tile_coord(in, "a link's start tile");
        l.end_tile = read_tile_coord(in, "a link's end tile");
        // A tile's file holds the links its tile owns (tile_links.h): one owned by another tile would
        // load with it and be lost when the tile is saved again.
        if (*l.start_tile != at)
            fail(ErrorCode::Parse, in.context(), ": link ", i, " starts on tile (", l.start_tile->x, ", ",
                 l.start_tile->z, "), not on the file's tile (", at.x, ", ", at.z, ")");
    }
    out.is_tile = true;
}

std::string tag_name(const uint8_t* tag) {
    std::string name;
    for (int i = 0; i < 4; ++i) name += (tag[i] >= 0x20 && tag[i] < 0x7f) ? char(tag[i]) : '?';
    return name;
}

}  // namespace

std::string made_for_json(const NavMeshFile& file) {
    const nlohmann::json out = {
        {"builder", file.made_for.builder.empty() ? nlohmann::json(nullptr) : nlohmann::json(file.made_for.builder)},
        {"builder_settings", recorded_json(file.made_for.builder_settings)},
        {"link_settings", recorded_json(file.made_for.links.settings)},
        {"link_plugins", recorded_json(file.made_for.links.plugins)},
        {"level_hash", level_hash_text(file.made_for.level_hash)},
        {"writer", file.writer}};
    // The names and texts come from the file: bytes that are not UTF-8 are shown as U+FFFD.
    return out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

uint32_t navmesh_file_checksum(const uint8_t* data, size_t size) {
    if (size <= kNavMeshFileHeaderBytes) return static_cast<uint32_t>(crc32_z(0L, Z_NULL, 0));
    return static_cast<uint32_t>(
        crc32_z(crc32_z(0L, Z_NULL, 0), data + kNavMeshFileHeaderBytes, size - kNavMeshFileHeaderBytes));
}

namespace {

// The file: MADE, GEOM, LINK, and TILE when `tile_hash` is given (a tile's file).
std::vector<uint8_t> write_file(const NavMeshInput& input, const std::vector<Link>& links,
                                const NavMeshProvenance& made_for, bool rides_carrier, const uint64_t* tile_hash) {
    Quantiser q;
    ByteWriter made, geometry, link_section, tile;
    write_made_for(made, input.agent_type, made_for, rides_carrier);
    write_geometry(geometry, input, q);
    write_links(link_section, links, q);
    if (tile_hash) write_tile(tile, input, links, *tile_hash);

    ByteWriter sections;
    write_section(sections, kMade, made);
    write_section(sections, kGeometry, geometry);
    write_section(sections, kLinks, link_section);
    if (tile_hash) write_section(sections, kTile, tile);
    // Deflated whole when that is smaller (it is, but for the smallest navmeshes).
    const std::vector<uint8_t>& body = sections.bytes();
    uLongf packed_size = compressBound(body.size());
    std::vector<uint8_t> packed(packed_size);
    const bool deflate = compress2(packed.data(), &packed_size, body.data(), body.size(), Z_BEST_COMPRESSION) == Z_OK &&
                         packed_size + 8 < body.size();

    ByteWriter out;
    for (uint8_t b : kMagic) out.u8(b);
    out.u32(kNavMeshFileVersion);
    out.u32(tile_hash ? 4 : 3);
    out.u64(0);  // the file's bytes, below
    out.u32(0);  // the checksum, below
    out.u32(deflate ? kDeflated : 0u);
    if (deflate) {
        packed.resize(packed_size);
        out.u64(body.size());
        out.append(packed);
    } else {
        out.append(body);
    }
    out.patch_u64(16, out.size());
    out.patch_u32(24, navmesh_file_checksum(out.bytes().data(), out.size()));
    return std::move(out.bytes());
}

}  // namespace

std::vector<uint8_t> write_navmesh_file(const NavMesh& navmesh, const std::vector<Link>& links,
                                        const NavMeshProvenance& made_for, bool rides_carrier) {
    return write_file(input_of(navmesh), links, made_for, rides_carrier, nullptr);
}

std::vector<uint8_t> write_tile_file(const NavMeshInput& tile, const std::vector<Link>& links,
                                     const NavMeshProvenance& made_for, uint64_t content_hash) {
    if (!tile.tiles.grid.tiled() || tile.tiles.tiles.size() != 1)
        fail(ErrorCode::InvalidArgument, "a tile's file holds one tile of a tiled navmesh");
    std::vector<Link> saved = links;
    for (Link& l : saved) l.start_polygon = l.end_polygon = kNoPolygon;  // placed where it is loaded
    return write_file(tile, saved, made_for, false, &content_hash);
}

std::string read_navmesh_file_bytes(const std::string& path) {
    return read_file_bytes_up_to_declared(
        path, kNavMeshFileHeaderBytes, kNavMeshFileMaxBytes,
        [](std::string_view header) -> uint64_t {
            if (header.size() < kNavMeshFileHeaderBytes || std::memcmp(header.data(), kMagic, sizeof(kMagic)) != 0)
                return 0;
            ByteReader in(reinterpret_cast<const uint8_t*>(header.data()), header.size(), "navmesh file");
            in.skip(sizeof(kMagic), "the magic bytes");
            if (in.u32("the format version") != kNavMeshFileVersion) return 0;  // read_navmesh_file names it
            in.skip(4, "the section count");
            return in.u64("the file size");
        },
        "navmesh file");
}

NavMeshFile read_navmesh_file(const uint8_t* data, size_t size) {
    if (!data) size = 0;
    ByteReader header(data, size, "navmesh file");
    if (size < sizeof(kMagic) || std::memcmp(data, kMagic, sizeof(kMagic)) != 0)
        fail(ErrorCode::VersionMismatch,
             "navmesh file: not a NavLink navmesh file (it does not start with the magic bytes "
             "89 'NLNAV' 0D 0A)");
    header.skip(sizeof(kMagic), "the magic bytes");
    NavMeshFile out;
    out.version = header.u32("the format version");
    if (out.version != kNavMeshFileVersion)
        fail(ErrorCode::VersionMismatch, "navmesh file: format version ", out.version, " (this NavLink reads version ",
             kNavMeshFileVersion, out.version > kNavMeshFileVersion ? "; the file is newer)" : ")");
    const uint32_t sections = header.u32("the section count");
    const uint64_t bytes = header.u64("the file size");
    const uint32_t checksum = header.u32("the checksum");
    const uint32_t flags = header.u32("the flags");
    if (bytes != size)
        fail(ErrorCode::Parse, "navmesh file: ", size < bytes ? "truncated" : "has extra bytes", ": its header says ",
             bytes, " bytes, there are ", size);
    if (checksum != navmesh_file_checksum(data, size))
        fail(ErrorCode::Parse, "navmesh file: corrupted: the checksum of its contents does not match its header's");

    if (flags & ~uint32_t(kDeflated)) fail(ErrorCode::Parse, "navmesh file: unknown flags 0x", std::hex, flags);
    std::vector<uint8_t> body;
    if (flags & kDeflated) {
        body = inflated(header.here(), header.remaining(), "navmesh file");
        header = ByteReader(body.data(), body.size(), "navmesh file");
    }

    bool made = false, geometry = false, links = false, tile = false;
    Quantiser q;
    for (uint32_t s = 0; s < sections; ++s) {
        header.need(16, "a section header");
        const std::string tag = tag_name(header.here());
        header.skip(4, "a section tag");
        header.u32("a section's reserved bytes");
        const uint64_t length = header.u64("a section's size");
        header.need(length, ("the " + tag + " section").c_str());
        ByteReader in(header.here(), static_cast<size_t>(length), "navmesh file: " + tag + " section");
        header.skip(static_cast<size_t>(length), "a section");
        bool* seen = nullptr;
        if (tag == "MADE") {
            read_made_for(in, out);
            seen = &made;
        } else if (tag == "GEOM") {
            read_geometry(in, out.navmesh, q);
            seen = &geometry;
        } else if (tag == "LINK") {
            if (!geometry) fail(ErrorCode::Parse, "navmesh file: the LINK section comes before GEOM");
            read_links(in, out.links, q);
            seen = &links;
        } else if (tag == "TILE") {
            if (!links) fail(ErrorCode::Parse, "navmesh file: the TILE section comes before LINK");
            read_tile(in, out);
            seen = &tile;
        } else {
            continue;  // a section of a later writer of this version: not needed to read the navmesh
        }
        if (*seen) fail(ErrorCode::Parse, "navmesh file: two ", tag, " sections");
        *seen = true;
        if (in.remaining() != 0)
            fail(ErrorCode::Parse, in.context(), ": ", in.remaining(), " bytes left over after it");
    }
    if (header.remaining() != 0)
        fail(ErrorCode::Parse, "navmesh file: ", header.remaining(), " bytes after its last section");
    if (!made || !geometry || !links)
        fail(ErrorCode::Parse, "navmesh file: the ",
             !made       ? "MADE"
             : !geometry ? "GEOM"
                         : "LINK",
             " section is missing");
    if (!tile) out.navmesh.weld_tolerance = 0.0f;  // a tile's is its own (TILE); a navmesh's is welded
    out.quantum = std::ldexp(1.0f, kNavMeshGridExponent);
    return out;
}

}  // namespace nl
