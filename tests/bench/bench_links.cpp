// navlink-bench-links [--stages] [--field N] [LEVEL.obj...]: link generation (jumps and drops) with
// default settings on the navmesh the built-in Recast builder makes with default settings. One line
// per level:
//   level=NAME tris=N edges=N samples=N jump=N drop=N bake_ms_1t=X bake_ms_2t=X bruteforce_ms=X same=yes|no
// The navmesh is built once; the same navmesh and level geometry are then baked by the generator
// nl_navmesh_generate_links runs (BakeMethod::Indexed: a grid of take-off points, the navmesh's
// polygon grid, a grid of link ends, one gathering of triangles per straight run of sweep pieces) on
// a world with one worker and on a world with two (best of 3 each), and once by the brute-force
// reference (BakeMethod::BruteForce: every pair of take-off points, every polygon, every kept link,
// every sweep piece gathered on its own; one worker). Both cast their rays through Embree. same=yes iff the reference's links equal the generator's (count, kind, start
// and end bit for bit, bidirectional flag, in order) and the one- and two-worker results are identical
// in every field. Exits 1 if any level says same=no (or fails to load), 2 on bad arguments.
//
// --field N adds the procedural level nl::levelgen::generate_large_level(1, N) (N x N blocks of 12 m,
// about 1,160 triangles per block; N = 14 gives about 230,000 triangles), named "large-N".
// --stages prints each bake's stage times (BakeReport milliseconds_*), counters and a fingerprint of
// its links (a hash of every field, to compare builds) to stderr.
#include <navlink/navlink.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <filesystem>
#include <string>
#include <vector>

#include "clock.h"
#include "level_generator.h"
#include "links/link_generator.h"
#include "world.h"

namespace {

bool g_stages = false;

// A level's geometry, from an OBJ file or generated.
struct Source {
    std::string name;
    std::string obj_path;                // empty: use `generated`
    nl::levelgen::GeneratedLevel generated;
};

struct World {
    nl_world* world = nullptr;
    World() = default;
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    ~World() { nl_world_destroy(world); }
};

bool fail(const Source& source, const char* what) {
    std::fprintf(stderr, "navlink-bench-links: %s: %s: %s\n", source.name.c_str(), what, nl_get_last_error_message());
    return false;
}

// Creates a world with `workers` threads holding the level's geometry; fills `triangles`.
bool load(const Source& source, int workers, World& out, uint32_t& triangles) {
    nl_world_def def = nl_default_world_def();
    def.worker_count = workers;
    if (NL_FAILED(nl_world_create(&def, &out.world))) return fail(source, "world");
    nl_mesh_id mesh{};
    if (!source.obj_path.empty()) {
        if (NL_FAILED(nl_mesh_add_obj_file(out.world, source.obj_path.c_str(), nullptr, &mesh))) return fail(source, "load");
    } else {
        nl_mesh_def def_mesh = nl_default_mesh_def();
        def_mesh.vertices = source.generated.positions.data();
        def_mesh.vertex_count = source.generated.vertex_count();
        def_mesh.indices = source.generated.indices.data();
        def_mesh.triangle_count = source.generated.triangle_count();
        if (NL_FAILED(nl_mesh_add(out.world, &def_mesh, &mesh))) return fail(source, "mesh");
    }
    nl_mesh_info info{};
    info.size = sizeof info;
    nl_mesh_get_info(out.world, mesh, &info);
    triangles = info.triangle_count;
    return true;
}

bool bits_equal(const nl::Vec3& a, const nl::Vec3& b) { return std::memcmp(a.data(), b.data(), 3 * sizeof(float)) == 0; }
bool bits_equal(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// What the reference must reproduce: count, kinds, ends bit for bit, bidirectional flags, in order.
bool same_link_set(const std::vector<nl::Link>& a, const std::vector<nl::Link>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].kind != b[i].kind || !bits_equal(a[i].start, b[i].start) || !bits_equal(a[i].end, b[i].end) ||
            a[i].bidirectional != b[i].bidirectional)
            return false;
    }
    return true;
}

// Thread counts must not change anything at all.
bool identical(const std::vector<nl::Link>& a, const std::vector<nl::Link>& b) {
    if (!same_link_set(a, b)) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        const nl::LinkRequirements &x = a[i].requirements, &y = b[i].requirements;
        if (!bits_equal(a[i].apex, b[i].apex) || a[i].generated != b[i].generated || a[i].enabled != b[i].enabled ||
            !bits_equal(a[i].cost_modifier, b[i].cost_modifier) || a[i].user_data != b[i].user_data ||
            !bits_equal(x.gap, y.gap) || !bits_equal(x.rise, y.rise) || !bits_equal(x.drop, y.drop) ||
            !bits_equal(x.clearance_width, y.clearance_width) || x.abilities != y.abilities ||
            a[i].start_polygon != b[i].start_polygon || a[i].end_polygon != b[i].end_polygon)
            return false;
    }
    return true;
}

struct Bake {
    std::vector<nl::Link> links;
    nl::BakeReport report;
    double ms = 1e300;
};

// Runs the generator `runs` times; keeps the fastest run's time and report (results are checked equal).
Bake bake(const nl::NavMesh& navmesh, nl_world& world, nl::BakeMethod method, int runs) {
    const nl::LinkSettings settings;  // the defaults, as nl_navmesh_generate_links with settings NULL
    Bake best;
    for (int run = 0; run < runs; ++run) {
        nl::BakeReport report;
        const double start = nl::samples::now_ms();
        std::vector<nl::Link> links = nl::generate_links(navmesh, *world.level, *world.tasks, settings, method, report,
                                                         [](float, const char*) { return true; });
        const double ms = nl::samples::now_ms() - start;
        if (run > 0 && !identical(links, best.links)) throw std::runtime_error("two runs of the same bake differ");
        if (ms < best.ms) {
            best.ms = ms;
            best.report = report;
        }
        best.links = std::move(links);
    }
    return best;
}

// FNV-1a over every field of every link, in order: compares results across builds (before and after
// an optimisation) without keeping them.
uint64_t fingerprint(const std::vector<nl::Link>& links) {
    uint64_t h = 1469598103934665603ull;
    auto mix = [&](const void* data, size_t size) {
        for (size_t i = 0; i < size; ++i) h = (h ^ static_cast<const unsigned char*>(data)[i]) * 1099511628211ull;
    };
    for (const nl::Link& l : links) {
        const uint32_t kind = static_cast<uint32_t>(l.kind);
        const uint8_t flags[3] = {l.bidirectional, l.generated, l.enabled};
        mix(&kind, sizeof kind);
        mix(l.start.data(), 12);
        mix(l.end.data(), 12);
        mix(l.apex.data(), 12);
        mix(flags, sizeof flags);
        mix(&l.cost_modifier, sizeof l.cost_modifier);
        mix(&l.user_data, sizeof l.user_data);
        const float req[4] = {l.requirements.gap, l.requirements.rise, l.requirements.drop, l.requirements.clearance_width};
        mix(req, sizeof req);
        mix(&l.requirements.abilities, sizeof l.requirements.abilities);
        mix(&l.start_polygon, sizeof l.start_polygon);
        mix(&l.end_polygon, sizeof l.end_polygon);
    }
    return h;
}

void print_stages(const std::string& level, const char* what, const Bake& b) {
    if (!g_stages) return;
    const nl::BakeReport& r = b.report;
    std::fprintf(stderr,
                 "  %s %s: total %.2f ms = edges %.2f + takeoff %.2f + jumps %.2f + drops %.2f + merge %.2f | groups %u "
                 "takeoffs %u jump_candidates %u drop_candidates %u rays %llu box_queries %llu | rejected distance %u rise %u angle %u "
                 "no_landing %u clearance %u duplicate %u wall %u not_ledge %u | links fingerprint %016llx\n",
                 level.c_str(), what, r.milliseconds_total, r.milliseconds_edges, r.milliseconds_takeoff,
                 r.milliseconds_jumps, r.milliseconds_drops, r.milliseconds_merge, r.groups, r.takeoff_points,
                 r.jump_candidates, r.drop_candidates, static_cast<unsigned long long>(r.rays_cast), static_cast<unsigned long long>(r.box_queries), r.rejected_distance,
                 r.rejected_rise, r.rejected_angle, r.rejected_no_landing, r.rejected_clearance, r.rejected_duplicate,
                 r.rejected_wall, r.rejected_not_ledge, static_cast<unsigned long long>(fingerprint(b.links)));
}

bool measure(const Source& source) {
    // The navmesh is built once, in the two-worker world (Recast's build is the slow part of a big
    // level); both worlds hold the same geometry, so it serves both.
    World one, two;
    uint32_t triangles = 0, triangles_again = 0;
    if (!load(source, 2, two, triangles) || !load(source, 1, one, triangles_again)) return false;
    const nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_navmesh_id id{};
    const double build_start = nl::samples::now_ms();
    if (NL_FAILED(nl_navmesh_build(two.world, &build, &id))) return fail(source, "navmesh build");
    const double build_ms = nl::samples::now_ms() - build_start;
    const auto navmesh = two.world->navmeshes->get(nl::Handle{id.index1, id.generation});
    if (g_stages)
        std::fprintf(stderr, "  %s: navmesh %u polygons, %zu boundary edges, built in %.0f ms\n", source.name.c_str(),
                     navmesh->polygon_count(), navmesh->boundary_edges().size(), build_ms);

    try {
        const Bake t1 = bake(*navmesh, *one.world, nl::BakeMethod::Indexed, 3);
        print_stages(source.name, "1 worker ", t1);
        const Bake t2 = bake(*navmesh, *two.world, nl::BakeMethod::Indexed, 3);
        print_stages(source.name, "2 workers", t2);
        const Bake reference = bake(*navmesh, *one.world, nl::BakeMethod::BruteForce, 1);
        print_stages(source.name, "all pairs", reference);
        const bool same = same_link_set(reference.links, t1.links) && identical(t1.links, t2.links);
        std::printf("level=%s tris=%u edges=%u samples=%u jump=%u drop=%u bake_ms_1t=%.1f bake_ms_2t=%.1f "
                    "bruteforce_ms=%.1f same=%s\n",
                    source.name.c_str(), triangles, t1.report.edges, t1.report.samples, t1.report.jump_links,
                    t1.report.drop_links, t1.ms, t2.ms, reference.ms, same ? "yes" : "no");
        std::fflush(stdout);
        return same;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "navlink-bench-links: %s: bake failed: %s\n", source.name.c_str(), e.what());
        return false;
    }
}

int usage() {
    std::fprintf(stderr, "usage: navlink-bench-links [--stages] [--field N] [LEVEL.obj...]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<Source> sources;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--stages") {
            g_stages = true;
        } else if (arg == "--field") {
            if (i + 1 >= argc) return usage();
            char* end = nullptr;
            const long blocks = std::strtol(argv[++i], &end, 10);
            if (*end != '\0' || blocks < 1 || blocks > 1000) return usage();
            Source s;
            s.name = "large-" + std::to_string(blocks);
            s.generated = nl::levelgen::generate_large_level(1, static_cast<uint32_t>(blocks));
            sources.push_back(std::move(s));
        } else if (!arg.empty() && arg[0] == '-') {
            return usage();
        } else {
            Source s;
            s.name = std::filesystem::path(arg).stem().string();
            s.obj_path = arg;
            sources.push_back(std::move(s));
        }
    }
    if (sources.empty()) return usage();
    bool ok = true;
    for (const Source& s : sources) ok = measure(s) && ok;
    return ok ? 0 : 1;
}
